// Film read-back (host/image/film.h): layers from their slots, in order, with their channel names.
#include "image/film.h"

#include <gtest/gtest.h>

#include "shared/film.h"

namespace rc {
namespace {

// Slot k of pixel p holds (100 p + 10 k, 100 p + 10 k + 1, 100 p + 10 k + 2, -1).
std::vector<shared::float4> numbered_film(int pixels, int slots) {
    std::vector<shared::float4> film;
    for (int p = 0; p < pixels; ++p) {
        for (int k = 0; k < slots; ++k) {
            const float base = 100.0f * p + 10.0f * k;
            film.push_back({base, base + 1.0f, base + 2.0f, -1.0f});
        }
    }
    return film;
}

TEST(Film, LayersComeFromTheirSlotsInTheOrderGiven) {
    const int slots = RC_CACHED_FILM_SLOTS;
    const Image image = unpack_film(numbered_film(6, slots), slots, 3, 2,
                                    {{"beauty", RC_CACHED_FILM_BEAUTY},
                                     {"coverage", RC_CACHED_FILM_COVERAGE, 1},
                                     {"records", RC_CACHED_FILM_LAYER}});
    ASSERT_EQ(image.channels, 7);
    const std::vector<std::string> names = {"R",         "G",         "B",        "coverage.Y",
                                            "records.R", "records.G", "records.B"};
    EXPECT_EQ(image.channel_names, names);
    for (int p = 0; p < 6; ++p) {
        const float* px = &image.pixels[static_cast<size_t>(p) * 7];
        const float base = 100.0f * p;
        EXPECT_EQ(px[0], base + 10.0f * RC_CACHED_FILM_BEAUTY);
        EXPECT_EQ(px[2], base + 10.0f * RC_CACHED_FILM_BEAUTY + 2.0f);
        EXPECT_EQ(px[3], base + 10.0f * RC_CACHED_FILM_COVERAGE);
        EXPECT_EQ(px[4], base + 10.0f * RC_CACHED_FILM_LAYER);
        EXPECT_EQ(px[6], base + 10.0f * RC_CACHED_FILM_LAYER + 2.0f);
    }
}

TEST(Film, SlotsStayDistinctAndInsideTheFilm) {
    const int caching[] = {RC_CACHED_FILM_BEAUTY, RC_CACHED_FILM_DIRECT, RC_CACHED_FILM_INDIRECT,
                           RC_CACHED_FILM_ALBEDO, RC_CACHED_FILM_NORMAL, RC_CACHED_FILM_COVERAGE,
                           RC_CACHED_FILM_LAYER};
    const int path[] = {RC_PT_FILM_BEAUTY,   RC_PT_FILM_BEAUTY_SQUARED, RC_PT_FILM_DIRECT,
                        RC_PT_FILM_INDIRECT, RC_PT_FILM_ALBEDO,         RC_PT_FILM_NORMAL};
    std::vector<bool> used(RC_CACHED_FILM_SLOTS, false);
    for (int slot : caching) {
        ASSERT_LT(slot, RC_CACHED_FILM_SLOTS);
        EXPECT_FALSE(used[slot]) << slot;
        used[slot] = true;
    }
    used.assign(RC_PT_FILM_SLOTS, false);
    for (int slot : path) {
        ASSERT_LT(slot, RC_PT_FILM_SLOTS);
        EXPECT_FALSE(used[slot]) << slot;
        used[slot] = true;
    }
}

}  // namespace
}  // namespace rc
