#include "hs/anatomy/PatientParams.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hs::anatomy::validatePatient;
using hs::clinical::PatientParams;

namespace {

std::string rejection(const PatientParams& p) {
    const auto status = validatePatient(p);
    EXPECT_FALSE(status.ok());
    if (status.ok())
        return {};
    EXPECT_EQ(status.error().code, hs::ErrorCode::InvalidInput);
    return status.error().detail;
}

} // namespace

TEST(PatientParams, DefaultsAreSupported) {
    EXPECT_TRUE(validatePatient(PatientParams{}).ok());
}

TEST(PatientParams, AgeOfFiveIsRejectedNamingTheParameterAndRange) {
    PatientParams p;
    p.ageYears = 5.0;
    const auto detail = rejection(p);
    EXPECT_NE(detail.find("ageYears"), std::string::npos);
    EXPECT_NE(detail.find("[18, 85]"), std::string::npos);
}

TEST(PatientParams, AgeOf130IsRejected) {
    PatientParams p;
    p.ageYears = 130.0;
    p.menopausal = true;
    EXPECT_NE(rejection(p).find("ageYears"), std::string::npos);
}

TEST(PatientParams, NegativeParityIsRejected) {
    PatientParams p;
    p.parity = -1;
    const auto detail = rejection(p);
    EXPECT_NE(detail.find("parity"), std::string::npos);
    EXPECT_NE(detail.find("[0, 6]"), std::string::npos);
}

TEST(PatientParams, NotANumberIsRejected) {
    PatientParams p;
    p.heightCm = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(rejection(p).find("heightCm"), std::string::npos);
    p = PatientParams{};
    p.weightKg = std::numeric_limits<double>::infinity();
    EXPECT_NE(rejection(p).find("weightKg"), std::string::npos);
}

TEST(PatientParams, GravidityBelowParityIsRejected) {
    PatientParams p;
    p.parity = 2;
    p.gravidity = 1;
    EXPECT_NE(rejection(p).find("gravidity"), std::string::npos);
}

TEST(PatientParams, MenopauseAtThirtyIsRejected) {
    PatientParams p;
    p.ageYears = 30.0;
    p.menopausal = true;
    EXPECT_NE(rejection(p).find("menopausal"), std::string::npos);
}
