// SPDX-License-Identifier: Apache-2.0
#include "distributed/frame_wire.hpp"

#include <cstring>
#include <stdexcept>

namespace fgr {
namespace {

class Writer {
public:
    template <typename T>
    void value(const T& v) {
        append(&v, sizeof v);
    }
    template <typename T>
    void array(const std::vector<T>& values) {
        value(uint64_t(values.size()));
        append(values.data(), values.size() * sizeof(T));
    }
    std::vector<uint8_t> bytes;

private:
    void append(const void* data, size_t size) {
        const auto* p = static_cast<const uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
    }
};

class Reader {
public:
    explicit Reader(std::span<const uint8_t> bytes) : bytes_(bytes) {}
    template <typename T>
    T value() {
        T v;
        take(&v, sizeof v);
        return v;
    }
    template <typename T>
    std::vector<T> array() {
        const auto count = value<uint64_t>();
        if (count > (bytes_.size() - offset_) / sizeof(T))
            throw std::runtime_error("a frame message is cut short");
        std::vector<T> values(count);
        take(values.data(), count * sizeof(T));
        return values;
    }
    bool at_end() const { return offset_ == bytes_.size(); }

private:
    void take(void* out, size_t size) {
        if (size > bytes_.size() - offset_)
            throw std::runtime_error("a frame message is cut short");
        if (size > 0) std::memcpy(out, bytes_.data() + offset_, size);
        offset_ += size;
    }
    std::span<const uint8_t> bytes_;
    size_t offset_ = 0;
};

}  // namespace

std::vector<uint8_t> frame_to_bytes(const Frame& frame) {
    Writer out;
    out.value(int32_t(frame.image.width));
    out.value(int32_t(frame.image.height));
    out.value(int32_t(frame.samples));
    out.value(int32_t(frame.double_precision));
    out.value(int64_t(frame.hits));
    out.value(frame.render_ms);
    out.array(frame.image.rgb);
    for (const auto* plane : {&frame.linear, &frame.depth, &frame.albedo, &frame.normal,
                              &frame.alpha, &frame.foreground}) {
        out.array(*plane);
    }
    return std::move(out.bytes);
}

Frame frame_from_bytes(std::span<const uint8_t> bytes) {
    Reader in(bytes);
    Frame frame;
    frame.image.width = in.value<int32_t>();
    frame.image.height = in.value<int32_t>();
    frame.samples = in.value<int32_t>();
    frame.double_precision = in.value<int32_t>() != 0;
    frame.hits = in.value<int64_t>();
    frame.render_ms = in.value<double>();
    frame.image.rgb = in.array<uint8_t>();
    for (auto* plane : {&frame.linear, &frame.depth, &frame.albedo, &frame.normal, &frame.alpha,
                        &frame.foreground}) {
        *plane = in.array<float>();
    }
    if (!in.at_end()) throw std::runtime_error("a frame message has bytes left over");
    return frame;
}

std::vector<uint8_t> tile_to_bytes(const EncodedTile& tile) {
    Writer out;
    out.value(int64_t(tile.hits));
    out.array(tile.rows);
    return std::move(out.bytes);
}

EncodedTile tile_from_bytes(std::span<const uint8_t> bytes) {
    Reader in(bytes);
    EncodedTile tile;
    tile.hits = in.value<int64_t>();
    tile.rows = in.array<uint8_t>();
    if (!in.at_end()) throw std::runtime_error("a tile message has bytes left over");
    return tile;
}

}  // namespace fgr
