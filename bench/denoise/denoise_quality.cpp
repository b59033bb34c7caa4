// SPDX-License-Identifier: Apache-2.0
// The denoiser against a reference (bench/denoise_quality.sh): the mean of two renders of half the
// samples denoised by each method, with and without features, and 1 - SSIM overall and on the
// pixels whose albedo or normal changes within 3x3 (the detail), against a many-sample render.
// Usage: denoise_quality HALF_A.exr HALF_B.exr REFERENCE.exr (the halves with --aov
// albedo,normal,depth).
#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "denoise/denoise.hpp"

struct Exr {
    int w, h;
    std::vector<float> rgb, albedo, normal, depth, alpha;
};

static std::vector<float> read_channels(Imf::InputFile& f, int w, int h,
                                        std::vector<std::string> names) {
    std::vector<float> v(size_t(w) * h * names.size(), 0.f);
    Imf::FrameBuffer fb;
    const Imath::Box2i dw = f.header().dataWindow();
    for (size_t c = 0; c < names.size(); ++c) {
        if (!f.header().channels().findChannel(names[c])) return {};
        char* base =
            (char*)(v.data() + c) - (dw.min.x + dw.min.y * w) * names.size() * sizeof(float);
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, base, names.size() * sizeof(float),
                                       names.size() * sizeof(float) * w));
    }
    f.setFrameBuffer(fb);
    f.readPixels(dw.min.y, dw.max.y);
    return v;
}
static Exr read(const std::string& path) {
    Imf::InputFile f(path.c_str());
    const Imath::Box2i dw = f.header().dataWindow();
    Exr e;
    e.w = dw.max.x - dw.min.x + 1;
    e.h = dw.max.y - dw.min.y + 1;
    e.rgb = read_channels(f, e.w, e.h, {"R", "G", "B"});
    e.albedo = read_channels(f, e.w, e.h, {"albedo.R", "albedo.G", "albedo.B"});
    e.normal = read_channels(f, e.w, e.h, {"normal.X", "normal.Y", "normal.Z"});
    e.depth = read_channels(f, e.w, e.h, {"depth.Z"});
    e.alpha = read_channels(f, e.w, e.h, {"A"});
    if (e.alpha.empty()) {
        e.alpha.assign(size_t(e.w) * e.h, 1.f);
        for (size_t i = 0; i < e.alpha.size(); ++i)
            if (!std::isfinite(e.depth.empty() ? 0.f : e.depth[i])) e.alpha[i] = 0.f;
    }
    for (float& z : e.depth)
        if (!std::isfinite(z)) z = -1.f;
    return e;
}

static float srgb(float l) {
    if (!(l > 0)) return 0;
    if (l >= 1) return 1;
    return l <= 0.0031308f ? 12.92f * l : 1.055f * std::pow(l, 1 / 2.4f) - 0.055f;
}
static std::vector<double> luma(const std::vector<float>& rgb) {
    std::vector<double> y(rgb.size() / 3);
    for (size_t i = 0; i < y.size(); ++i)
        y[i] = 0.2126 * srgb(rgb[3 * i]) + 0.7152 * srgb(rgb[3 * i + 1]) +
               0.0722 * srgb(rgb[3 * i + 2]);
    return y;
}
// SSIM map (Wang 2004, 11x11 Gaussian 1.5), valid windows only; map index = centre pixel.
static std::vector<double> means(const std::vector<double>& p, int w, int h) {
    double g[11], s = 0;
    for (int i = 0; i < 11; ++i) {
        double d = i - 5;
        g[i] = std::exp(-d * d / 4.5);
        s += g[i];
    }
    for (double& x : g) x /= s;
    int ow = w - 10, oh = h - 10;
    std::vector<double> r(size_t(ow) * h), o(size_t(ow) * oh);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < ow; ++x) {
            double a = 0;
            for (int k = 0; k < 11; ++k) a += g[k] * p[size_t(y) * w + x + k];
            r[size_t(y) * ow + x] = a;
        }
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            double a = 0;
            for (int k = 0; k < 11; ++k) a += g[k] * r[size_t(y + k) * ow + x];
            o[size_t(y) * ow + x] = a;
        }
    return o;
}
static std::vector<double> ssim_map(const std::vector<double>& x, const std::vector<double>& y,
                                    int w, int h) {
    size_t n = x.size();
    std::vector<double> xx(n), yy(n), xy(n);
    for (size_t i = 0; i < n; ++i) {
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    auto mx = means(x, w, h), my = means(y, w, h), exx = means(xx, w, h), eyy = means(yy, w, h),
         exy = means(xy, w, h);
    const double c1 = 1e-4, c2 = 9e-4;
    std::vector<double> m(mx.size());
    for (size_t i = 0; i < m.size(); ++i) {
        double vx = exx[i] - mx[i] * mx[i], vy = eyy[i] - my[i] * my[i],
               cv = exy[i] - mx[i] * my[i];
        m[i] = (2 * mx[i] * my[i] + c1) * (2 * cv + c2) /
               ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    return m;
}

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: denoise_quality HALF_A.exr HALF_B.exr REFERENCE.exr\n");
        return 2;
    }
    Exr a = read(argv[1]), b = read(argv[2]), ref = read(argv[3]);
    Exr feat = argc > 4 ? read(argv[4]) : a;
    int w = a.w, h = a.h;
    size_t n = size_t(w) * h;
    std::vector<float> mean(3 * n), var(3 * n);
    for (size_t i = 0; i < 3 * n; ++i) {
        mean[i] = 0.5f * (a.rgb[i] + b.rgb[i]);
        float d = a.rgb[i] - b.rgb[i];
        var[i] = d * d / 4;
    }
    std::vector<float> albedo(3 * n), normal(3 * n), depth(n), alpha(n);
    for (size_t i = 0; i < 3 * n; ++i) {
        albedo[i] = 0.5f * (a.albedo[i] + b.albedo[i]);
        normal[i] = 0.5f * (a.normal[i] + b.normal[i]);
    }
    for (size_t i = 0; i < n; ++i) {
        depth[i] = a.depth[i];
        alpha[i] = 0.5f * (a.alpha[i] + b.alpha[i]);
    }
    // mask: albedo or normal changes within 3x3 (on the feature render)
    std::vector<char> mask(n, 0);
    size_t masked = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t p = size_t(y) * w + x;
            float best = 0, bestn = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    size_t q = size_t(qy) * w + qx;
                    for (int c = 0; c < 3; ++c) {
                        best = std::max(best,
                                        std::fabs(feat.albedo[3 * p + c] - feat.albedo[3 * q + c]));
                        bestn = std::max(
                            bestn, std::fabs(feat.normal[3 * p + c] - feat.normal[3 * q + c]));
                    }
                }
            mask[p] = best > 0.05f || bestn > 0.1f;
            masked += mask[p];
        }
    auto report = [&](const char* name, const std::vector<float>& img, double ms) {
        auto m = ssim_map(luma(img), luma(ref.rgb), w, h);
        double all = 0, sel = 0;
        size_t cs = 0;
        for (int y = 5; y < h - 5; ++y)
            for (int x = 5; x < w - 5; ++x) {
                double v = m[size_t(y - 5) * (w - 10) + x - 5];
                all += v;
                if (mask[size_t(y) * w + x]) {
                    sel += v;
                    ++cs;
                }
            }
        all /= double(m.size());
        sel /= double(std::max<size_t>(cs, 1));
        double se = 0;
        for (size_t i = 0; i < 3 * n; ++i) {
            double d = img[i] - ref.rgb[i];
            se += d * d;
        }
        printf("%-10s 1-SSIM %.4f  detail 1-SSIM %.4f  (SSIM %.4f)  RMSE %.5f  %.1f ms\n", name,
               1 - all, 1 - sel, sel, std::sqrt(se / (3 * n)), ms);
    };
    printf("%dx%d, detail pixels %.1f%%\n", w, h, 100.0 * masked / n);
    report("noisy", mean, 0);
    for (auto method : {fgr::DenoiseMethod::Atrous, fgr::DenoiseMethod::NlMeans,
                        fgr::DenoiseMethod::Regression}) {
        fgr::DenoiseInput in{w, h, mean, var, albedo, normal, depth, alpha};
        double best = 1e9;
        std::vector<float> out;
        for (int r = 0; r < 3; ++r) {
            auto t0 = std::chrono::steady_clock::now();
            out = fgr::denoise(in, {method, 0});
            best = std::min(best, std::chrono::duration<double, std::milli>(
                                      std::chrono::steady_clock::now() - t0)
                                      .count());
        }
        report(fgr::denoise_method_name(method), out, best);
        fgr::DenoiseInput blind{w, h, mean, var};
        const char* blind_name = method == fgr::DenoiseMethod::Atrous    ? "a-t blind"
                                 : method == fgr::DenoiseMethod::NlMeans ? "nlm blind"
                                                                         : "reg blind";
        report(blind_name, fgr::denoise(blind, {method, 0}), 0);
    }
}
