// The review file reader (ratings beside a package). Property: an error names the source.

#include "FuzzSupport.h"
#include "hs/scene/Review.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto review = hs::scene::parseReview(text, "fuzz.review.json");
    if (!review.ok())
        hs::fuzz::check(review.error().detail.find("fuzz.review.json") != std::string::npos,
                        "an error names the source", review.error().detail);
    else
        hs::fuzz::check(hs::scene::parseReview(hs::scene::toJson(*review), "written.json").ok(),
                        "an accepted review, written, reads back");
    return 0;
}
