// SPDX-License-Identifier: Apache-2.0
// The tile store of a tiled still (output/tiled/tile_store.hpp) trusts nothing it reads back: a
// band file whose header does not fit the band (its number, size or hit count), that is truncated
// or not a regular file (a FIFO must not block --resume, a directory must not abort it) is
// rejected with one warning line and removed for the band to be rendered again; a render.json
// that is not one is a one-line error naming the file. Pure host: no device.
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "fuzz_rng.hpp"
#include "json_mutation.hpp"
#include "output/tiled/tile_store.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// The header fields' offsets in a band file (tile_store.cpp's BandHeader).
constexpr size_t kBandOffset = 8, kReservedOffset = 12, kRawOffset = 16, kCompressedOffset = 24,
                 kHitsOffset = 32, kHeaderBytes = 40;

std::vector<uint8_t> some_rows(test::FuzzRng& rng, size_t bytes) {
    std::vector<uint8_t> rows(bytes);
    // Runs of equal bytes, as encoded pixels have, so that compression has something to do.
    for (size_t i = 0; i < bytes; ++i)
        rows[i] = i > 0 && rng.chance(0.7) ? rows[i - 1] : static_cast<uint8_t>(rng.below(256));
    return rows;
}

template <typename T>
void put(std::string& bytes, size_t offset, T value) {
    if (offset + sizeof value <= bytes.size())
        std::memcpy(bytes.data() + offset, &value, sizeof value);
}

// Warnings fgr logs while it lives, one string.
class CapturedLog {
public:
    CapturedLog()
        : previous_(spdlog::default_logger()),
          logger_(std::make_shared<spdlog::logger>(
              "captured", std::make_shared<spdlog::sinks::ostream_sink_mt>(text_))) {
        logger_->set_pattern("%l: %v");
        spdlog::set_default_logger(logger_);
    }
    ~CapturedLog() { spdlog::set_default_logger(previous_); }
    std::string text() const { return text_.str(); }

private:
    std::ostringstream text_;
    std::shared_ptr<spdlog::logger> previous_, logger_;
};

// Random rows and hit counts, encoded, then damaged as a disk, a crash or a person might: cut
// short, a header field set to a nasty value, bytes flipped or appended. Decoding never crashes,
// and what it accepts is a band of the geometry asked for: its hits within its pixels, and
// exactly the rows written whenever the file is the one written.
TEST(FuzzTileBand, SeededCasesNeverCrash) {
    const uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed();
    const int64_t nasty[] = {0,         -1,        1,         255,      1LL << 31, -(1LL << 31),
                             1LL << 32, INT64_MAX, INT64_MIN, 136580477};
    for (uint64_t i = 0; i < cases; ++i) {
        const uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        const int band = rng.range(0, 40);
        const long pixels = rng.range(1, 48);
        const size_t pixel_bytes =
            rng.pick({size_t{3}, size_t{4}, size_t{6}, size_t{8}, size_t{16}});
        const std::vector<uint8_t> rows = some_rows(rng, size_t(pixels) * pixel_bytes);
        const long hits = rng.range(0, int(pixels));
        const std::string written = encode_band(band, rows, hits);
        std::string bytes = written;
        switch (rng.below(6)) {
            case 0:
                bytes.resize(rng.below(bytes.size()));
                break;
            case 1: {
                const size_t offsets[] = {0,          kBandOffset,       kReservedOffset,
                                          kRawOffset, kCompressedOffset, kHitsOffset};
                const size_t offset = rng.pick(offsets);
                const int64_t value = rng.pick(nasty);
                if (offset == kBandOffset || offset == kReservedOffset) {
                    put(bytes, offset, static_cast<uint32_t>(value));
                } else {
                    put(bytes, offset, value);
                }
                break;
            }
            case 2:
                for (int n = rng.range(1, 4); n > 0; --n)
                    bytes[rng.below(bytes.size())] ^= char(1 + rng.below(255));
                break;
            case 3:
                bytes += std::string(rng.range(1, 64), char(rng.below(256)));
                break;
            case 4:
                put(bytes, kHitsOffset, int64_t{pixels} + rng.range(1, 1000));
                break;
            default:
                break;  // as written
        }
        std::vector<uint8_t> decoded(rows.size());
        long decoded_hits = -7;
        const std::string why = decode_band(bytes, band, pixels, decoded, decoded_hits);
        if (bytes == written) {
            ASSERT_EQ(why, "") << "seed " << seed;
            ASSERT_EQ(decoded, rows) << "seed " << seed;
            ASSERT_EQ(decoded_hits, hits) << "seed " << seed;
        } else if (why.empty()) {
            ASSERT_GE(decoded_hits, 0) << "seed " << seed;
            ASSERT_LE(decoded_hits, pixels) << "seed " << seed;
        } else {
            ASSERT_EQ(why.find('\n'), std::string::npos) << "seed " << seed;
        }
        // Another band's number, or a band of another size, is never taken for this one.
        std::vector<uint8_t> other(rows.size() + pixel_bytes);
        ASSERT_NE(decode_band(written, band + 1, pixels, decoded, decoded_hits), "") << seed;
        ASSERT_NE(decode_band(written, band, pixels, other, decoded_hits), "") << seed;
    }
}

class TileStoreTest : public ::testing::Test {
protected:
    static constexpr long kPixels = 48;
    static constexpr size_t kRowBytes = kPixels * 3;

    // The store of a render whose identity is {"scene": "a"}, resumed when it exists.
    std::unique_ptr<TileStore> open(bool resume = true) {
        return std::make_unique<TileStore>(store_, nlohmann::json{{"scene", "a"}}, resume, output_);
    }

    // A store holding band 0 and band 1 as written.
    void make_store() {
        auto store = open(false);
        test::FuzzRng rng(1);
        rows_ = some_rows(rng, kRowBytes);
        store->save_band(0, rows_, 17);
        store->save_band(1, rows_, 18);
    }

    // Loads band 0 with `store`, checking it is rejected, in one warning line naming the file, and
    // that band 1 is still taken.
    void expect_band_zero_rejected(const std::string& why) {
        CapturedLog log;
        auto store = open();
        std::vector<uint8_t> rows(kRowBytes);
        EXPECT_FALSE(store->load_band(0, kPixels, rows).has_value()) << why;
        const std::string warned = log.text();
        EXPECT_NE(warned.find("band_000000.z"), std::string::npos) << warned;
        size_t warnings = 0;
        for (size_t at = warned.find("warning:"); at != std::string::npos;
             at = warned.find("warning:", at + 1)) {
            ++warnings;
        }
        EXPECT_EQ(warnings, 1u) << warned;
        EXPECT_FALSE(fs::exists(fs::symlink_status(band_zero()))) << "removed for the new band";
        EXPECT_EQ(store->load_band(1, kPixels, rows), 18L);
        // The band rendered again takes the place of what was there.
        store->save_band(0, rows_, 17);
        EXPECT_EQ(store->load_band(0, kPixels, rows), 17L);
        EXPECT_EQ(rows, rows_);
    }

    fs::path band_zero() const { return store_ / "band_000000.z"; }

    test::TempDir temp_{"fgr_tile_store"};
    fs::path output_ = temp_.path() / "out.png";
    fs::path store_ = temp_.path() / "out.png.fgr-tiles";
    std::vector<uint8_t> rows_;
};

TEST_F(TileStoreTest, TakesTheBandsItWrote) {
    make_store();
    auto store = open();
    std::vector<uint8_t> rows(kRowBytes);
    EXPECT_EQ(store->load_band(0, kPixels, rows), 17L);
    EXPECT_EQ(rows, rows_);
    EXPECT_FALSE(store->load_band(2, kPixels, rows).has_value()) << "not there";
}

// --resume once printed 136,580,477 hits for a 24-megapixel image from one edited band header.
TEST_F(TileStoreTest, ABandWithMoreHitsThanPixelsIsRenderedAgain) {
    make_store();
    std::string bytes = test::read_file(band_zero());
    put(bytes, kHitsOffset, int64_t{136580477});
    test::write_text(band_zero(), bytes);
    expect_band_zero_rejected("hits");
}

TEST_F(TileStoreTest, ABandOfAnotherSizeIsRenderedAgain) {
    make_store();
    auto store = open();
    std::vector<uint8_t> wider(kRowBytes + 3);
    EXPECT_FALSE(store->load_band(0, kPixels + 1, wider).has_value());
}

// A FIFO named like a band once blocked --resume forever in the open.
TEST_F(TileStoreTest, AFifoNamedLikeABandIsRenderedAgainWithoutBlocking) {
    make_store();
    fs::remove(band_zero());
    ASSERT_EQ(::mkfifo(band_zero().c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    expect_band_zero_rejected("fifo");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

// A directory named like a band once aborted --resume.
TEST_F(TileStoreTest, ADirectoryNamedLikeABandIsRenderedAgain) {
    make_store();
    fs::remove(band_zero());
    fs::create_directories(band_zero() / "inside");
    expect_band_zero_rejected("directory");
}

TEST_F(TileStoreTest, ATruncatedBandIsRenderedAgain) {
    make_store();
    std::string bytes = test::read_file(band_zero());
    test::write_text(band_zero(), bytes.substr(0, kHeaderBytes + 3));
    expect_band_zero_rejected("truncated");
}

// A render.json that is not one is a one-line error naming the file, whatever is wrong with it.
TEST_F(TileStoreTest, ADamagedRenderJsonIsAOneLineErrorNamingIt) {
    make_store();
    const fs::path manifest = store_ / "render.json";
    const std::vector<std::string> damaged{
        "",
        "{",
        "{\"fgr_tile_store\": 1, \"render\": {\"scene\": \"a\"}} trailing",
        "[1, 2, 3]",
        "{\"fgr_tile_store\": \"1\", \"render\": {\"scene\": \"a\"}}",
        "{\"fgr_tile_store\": 1, \"render\": [\"scene\"]}",
        "{\"fgr_tile_store\": 2, \"render\": {\"scene\": \"a\"}}",
        std::string(2 << 20, ' '),
        "{\"fgr_tile_store\": 1, \"render\": {\"scene\": \"" + std::string(100000, 'b') + "\"}}",
    };
    for (const std::string& text : damaged) {
        test::write_text(manifest, text);
        try {
            open();
            ADD_FAILURE() << "taken: " << text.substr(0, 80);
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            // The file that is wrong, or for a store of another render, the store.
            const bool foreign = text.size() > 1000 && text.front() == '{';
            EXPECT_NE(message.find(foreign ? store_.string() : manifest.string()),
                      std::string::npos)
                << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
        }
    }
    fs::remove(manifest);
    fs::create_directory(manifest);
    EXPECT_THROW(open(), std::runtime_error);
    fs::remove(manifest);
    ASSERT_EQ(::mkfifo(manifest.c_str(), 0600), 0);
    EXPECT_THROW(open(), std::runtime_error) << "a FIFO is refused, not waited on";
}

// render.json mutated as a person, a disk or a hostile file might (deep nesting, duplicate keys,
// huge numbers, wrong types, truncation, stray bytes): resuming either takes a store whose
// identity still matches or refuses in one short line, never a crash or the JSON library's text.
TEST(FuzzTileStoreManifest, SeededCasesResumeOrRefuseInOneLine) {
    const test::TempDir temp("fgr_tile_store_fuzz");
    const fs::path store = temp.path() / "out.png.fgr-tiles";
    const fs::path output = temp.path() / "out.png";
    const nlohmann::json identity = {{"scene", "mandelbulb"},
                                     {"samples", 4},
                                     {"seed", 0},
                                     {"size", "64x48"},
                                     {"view", "eye 0 0 3 target 0 0 0 up 0 1 0 fov 45"},
                                     {"tiles", "16 rows a band, 64 columns a tile, 4 padding"}};
    TileStore(store, identity, false, output);
    const std::string written = test::read_file(store / "render.json");
    const uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed(20261129);
    for (uint64_t i = 0; i < cases; ++i) {
        const uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        std::string text = written;
        test::mutate_document(text, rng, 1 + int(rng.below(3)));
        test::write_text(store / "render.json", text);
        try {
            TileStore(store, identity, true, output);
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            ASSERT_EQ(message.find('\n'), std::string::npos) << "seed " << seed << ": " << message;
            ASSERT_LT(message.size(), 400u) << "seed " << seed << ": " << message.substr(0, 400);
            ASSERT_EQ(message.find("json.exception"), std::string::npos) << "seed " << seed;
        }
    }
}

}  // namespace
}  // namespace fgr
