#include "hs/core/Result.h"

#include <gtest/gtest.h>

#include <string>

namespace {

hs::Result<int> parsePositive(int v) {
    if (v <= 0)
        return hs::fail(hs::ErrorCode::InvalidInput, "value " + std::to_string(v) + " must be > 0");
    return v;
}

hs::Status chain(int v) {
    HS_TRY(parsePositive(v));
    return {};
}

} // namespace

TEST(Result, CarriesAValue) {
    auto r = parsePositive(3);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(*r, 3);
}

TEST(Result, CarriesAnErrorWithCodeAndDetail) {
    auto r = parsePositive(-1);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, hs::ErrorCode::InvalidInput);
    EXPECT_EQ(r.error().message(), "invalid-input: value -1 must be > 0");
}

TEST(Result, TryPropagatesTheFirstFailure) {
    EXPECT_TRUE(chain(1).ok());
    const auto s = chain(0);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("must be > 0"), std::string::npos);
}
