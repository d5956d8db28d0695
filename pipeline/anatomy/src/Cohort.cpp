#include "hs/anatomy/Cohort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace hs::anatomy {

namespace {

// ---- Population (assumptions of typical adult women seen for hysteroscopy; see docs/anatomy.md) ----
constexpr double kAgeMean = 42.0, kAgeSd = 13.0;            ///< years
constexpr double kMenopauseMean = 51.0, kMenopauseSd = 3.5; ///< years; median natural menopause about 51
constexpr double kHeightMean = 164.0, kHeightSd = 7.0;      ///< cm
constexpr double kBmiMean = 25.5, kBmiSd = 4.5;             ///< kg/m^2

// ---- Relations (docs/anatomy.md gives the source of each; docs/references.md lists the sources) ----
/// Post-menopausal atrophy of linear dimensions per year since menopause, so that the length falls from about 72 mm
/// at 40 to about 42-45 mm at 80 (Verguts et al. 2013).
constexpr double kAtrophyPerYear = 0.017;
constexpr double kAtrophyFloor = 0.45;
/// AP diameter falls about 22 % across the menopause (2 years before to 2 years after).
constexpr double kMenopauseApFactor = 0.78;

// ---- Natural variation around the relations (SD, mm, at the reference size named; scaled with the organ) ----
// Chosen so that the population spread matches the published SDs and 95 % ranges once the spread of ages and
// parities is added (see docs/anatomy.md).
constexpr double kCervixLengthSd = 2.8;   ///< mm at a 30 mm cervix
constexpr double kCervixDiameterSd = 2.2; ///< mm at 29 mm
constexpr double kCavityLengthSd = 2.0;   ///< mm, before atrophy
constexpr double kCavityWidthSd = 2.2;    ///< mm, before atrophy; the organ's width follows it
constexpr double kCavityDepthSd = 1.2;    ///< mm, before atrophy
constexpr double kFundalWallSd = 1.2;     ///< mm at 12 mm
constexpr double kWidthSd = 2.2;          ///< mm at 45 mm, besides the cavity's share
constexpr double kApDepthSd = 3.5;        ///< mm at 40 mm

int drawIndex(Rng& rng, const double* weights, int n) {
    double u = rng.uniform();
    for (int i = 0; i < n; ++i) {
        if (u < weights[i])
            return i;
        u -= weights[i];
    }
    return n - 1;
}

/// Piecewise-linear interpolation through (x, y) knots, constant beyond the ends.
double interpolate(double x, std::initializer_list<std::array<double, 2>> knots) {
    const auto* k = knots.begin();
    if (x <= (*k)[0])
        return (*k)[1];
    for (const auto* it = k + 1; it != knots.end(); ++it) {
        if (x <= (*it)[0]) {
            const auto& a = *(it - 1);
            const auto& b = *it;
            return a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
        }
    }
    return (*(knots.end() - 1))[1];
}

/// Fundal wall thickness by age: 10.8 / 12.3 / 13.6 mm for 15-24 / 25-34 / 35-45 years (group midpoints).
double fundalWallByAge(double age) {
    return interpolate(age, {{19.5, 10.8}, {29.5, 12.3}, {40.0, 13.6}});
}
/// Intercornual (outer transverse) width by age: 41.4 / 44.5 / 47.2 mm for the same groups.
double widthByAge(double age) {
    return interpolate(age, {{19.5, 41.4}, {29.5, 44.5}, {40.0, 47.2}});
}

double atrophy(double yearsSinceMenopause, double rateScale) {
    return std::max(kAtrophyFloor, 1.0 - rateScale * kAtrophyPerYear * yearsSinceMenopause);
}

/// The relations' means and the standard deviations of the natural variation around them.
struct Relations {
    UterusShapeParams mean;
    double yearsPost = 0.0;
};

Relations relations(const clinical::PatientParams& p, double menopauseAge) {
    Relations r;
    const double births = std::min(p.parity, 4);
    const double births2 = std::min(p.parity, 2);
    const double lost = std::min(p.gravidity - p.parity, 4); ///< pregnancies that did not end in a birth
    const double h = (p.heightCm - kHeightMean) / 10.0;
    r.yearsPost = p.menopausal ? std::max(0.0, p.ageYears - menopauseAge) : 0.0;
    const double age = std::min(p.ageYears, 45.0);
    const double y = r.yearsPost;
    auto& m = r.mean;
    // Cervix: 30.8 vs 29.2 mm long, AP 27.8 vs 31.5 mm (nulliparous vs multiparous).
    m.cervixLengthMm = (30.8 - 0.8 * births2) * atrophy(y, 0.8);
    m.cervixDiameterMm = (27.8 + 1.85 * births2) * atrophy(y, 0.5);
    // Cavity: length 26-38 mm (95 %), longer after births; width 27 mm nulliparous vs 32 mm after more than one
    // pregnancy, 25-40 mm (95 %); internal os 4-11 mm; cornual angle 39-88 degree (Chen et al.).
    m.cavityLengthMm = (30.5 + 1.2 * births + 0.3 * lost + 0.6 * h) * atrophy(y, 1.0);
    m.cavityWidthMm = (27.0 + 2.5 * births2) * atrophy(y, 1.0);
    m.cavityDepthMm = (8.0 + 0.3 * births) * atrophy(y, 1.0);
    m.internalOsWidthMm = 7.5 * atrophy(y, 1.0);
    m.cornualAngleDeg = 63.5;
    // Fundal wall by age; the wall atrophies more slowly than the cavity.
    m.fundalWallMm = fundalWallByAge(age) * atrophy(y, 0.6);
    // Outer width (intercornual distance by age), raised by gravidity (Verguts et al. 2013).
    m.widthMm = (widthByAge(p.ageYears) + 0.8 * births + 0.3 * lost) * atrophy(y, 0.6);
    // AP: 45.0 +- 8.1 mm in gravida 0 (Gao et al. 2018), raised by gravidity, -22 % across the menopause.
    m.apDepthMm = (38.0 + 1.5 * births + 0.3 * lost) * (p.menopausal ? kMenopauseApFactor : 1.0) * atrophy(y, 0.5);
    m.flexionDeg = 15.0;
    m.versionDeg = 0.0;
    m.lengthMm = m.cervixLengthMm + m.cavityLengthMm + m.fundalWallMm;
    return r;
}

} // namespace

clinical::PatientParams samplePatient(Rng& rng, double* menopauseAgeYears) {
    clinical::PatientParams p;
    p.ageYears = rng.truncatedNormal(kAgeMean, kAgeSd, 18.0, 85.0);
    const double menopause = rng.truncatedNormal(kMenopauseMean, kMenopauseSd, 40.0, 60.0);
    p.menopausal = p.ageYears >= menopause;
    // Parity by age group (assumed distributions of a Western population).
    static const double young[] = {0.75, 0.20, 0.05};
    static const double twenties[] = {0.45, 0.30, 0.18, 0.05, 0.02};
    static const double older[] = {0.20, 0.20, 0.35, 0.15, 0.06, 0.03, 0.01};
    if (p.ageYears < 22.0)
        p.parity = drawIndex(rng, young, 3);
    else if (p.ageYears < 30.0)
        p.parity = drawIndex(rng, twenties, 5);
    else
        p.parity = drawIndex(rng, older, 7);
    static const double extra[] = {0.60, 0.28, 0.09, 0.03};
    p.gravidity = std::min(10, p.parity + drawIndex(rng, extra, 4));
    p.heightCm = rng.truncatedNormal(kHeightMean, kHeightSd, 140.0, 195.0);
    const double bmi = rng.truncatedNormal(kBmiMean, kBmiSd, 17.0, 45.0);
    p.weightKg = std::clamp(bmi * (p.heightCm / 100.0) * (p.heightCm / 100.0), 35.0, 160.0);
    if (menopauseAgeYears)
        *menopauseAgeYears = menopause;
    return p;
}

clinical::PatientParams sampleSupportedPatient(Rng& rng) {
    clinical::PatientParams p;
    p.ageYears = rng.uniform(18.0, 85.0);
    p.menopausal = p.ageYears > 60.0 || (p.ageYears >= 40.0 && rng.bernoulli((p.ageYears - 40.0) / 20.0));
    p.parity = static_cast<int>(rng.between(0, 6));
    p.gravidity = p.parity + static_cast<int>(rng.between(0, std::min(4, 10 - p.parity)));
    p.heightCm = rng.uniform(140.0, 195.0);
    p.weightKg = rng.uniform(35.0, 160.0);
    return p;
}

UterusShapeParams expectedShape(const clinical::PatientParams& patient) {
    return relations(patient, kMenopauseMean).mean;
}

ExpectedDimensions expectedDimensions(const clinical::PatientParams& patient) {
    const Relations r = relations(patient, kMenopauseMean);
    const auto& m = r.mean;
    const double shrink = atrophy(r.yearsPost, 1.0);
    const double cervixSd = kCervixLengthSd * m.cervixLengthMm / 30.0;
    const double cavityLengthSd = kCavityLengthSd * shrink;
    const double cavityWidthSd = kCavityWidthSd * shrink;
    const double fundalSd = kFundalWallSd * m.fundalWallMm / 12.0;
    const double widthOwnSd = kWidthSd * m.widthMm / 45.0;
    ExpectedDimensions e;
    e.lengthMm = {m.lengthMm, std::sqrt(cervixSd * cervixSd + cavityLengthSd * cavityLengthSd + fundalSd * fundalSd)};
    e.widthMm = {m.widthMm, std::sqrt(cavityWidthSd * cavityWidthSd + widthOwnSd * widthOwnSd)};
    e.apDepthMm = {m.apDepthMm, kApDepthSd * m.apDepthMm / 40.0};
    e.cavityLengthMm = {m.cavityLengthMm, cavityLengthSd};
    e.cavityWidthMm = {m.cavityWidthMm, cavityWidthSd};
    e.fundalWallMm = {m.fundalWallMm, fundalSd};
    e.cervixLengthMm = {m.cervixLengthMm, cervixSd};
    return e;
}

UterusShapeParams sampleShape(const clinical::PatientParams& patient, double menopauseAgeYears, Rng& rng) {
    const Relations r = relations(patient, menopauseAgeYears);
    UterusShapeParams s = r.mean;
    const double shrink = atrophy(r.yearsPost, 1.0);
    // Natural variation: standard deviations chosen so that the population spread matches the published SDs and
    // 95 % ranges once the spread of ages and parities is added (see docs/anatomy.md). The variation is
    // proportional to size (a constant coefficient of variation), so small atrophic organs vary less in mm.
    const auto& m = r.mean;
    s.cervixLengthMm += rng.normal(0.0, kCervixLengthSd) * m.cervixLengthMm / 30.0;
    s.cervixDiameterMm += rng.normal(0.0, kCervixDiameterSd) * m.cervixDiameterMm / 29.0;
    const double cavityWidthNoise = rng.normal(0.0, kCavityWidthSd) * shrink;
    s.cavityLengthMm += rng.normal(0.0, kCavityLengthSd) * shrink;
    s.cavityWidthMm += cavityWidthNoise;
    s.cavityDepthMm = std::max(2.0, s.cavityDepthMm + rng.normal(0.0, kCavityDepthSd) * shrink);
    // The canal narrows with the atrophy after menopause, like the cavity.
    s.internalOsWidthMm = rng.truncatedNormal(7.5, 1.75, 4.0, 11.0) * shrink;
    s.cornualAngleDeg = rng.truncatedNormal(63.5, 12.3, 35.0, 92.0);
    s.fundalWallMm = std::max(6.0, s.fundalWallMm + rng.normal(0.0, kFundalWallSd) * m.fundalWallMm / 12.0);
    // A wider cavity comes with a wider organ.
    s.widthMm += cavityWidthNoise + rng.normal(0.0, kWidthSd) * m.widthMm / 45.0;
    s.apDepthMm += rng.normal(0.0, kApDepthSd) * m.apDepthMm / 40.0;
    // Version and flexion: anteverted-anteflexed is most common, about 20 % are retroverted (docs/references.md
    // [Retroversion]).
    const bool retroverted = rng.bernoulli(0.2);
    s.versionDeg =
        retroverted ? rng.truncatedNormal(-25.0, 10.0, -60.0, -5.0) : rng.truncatedNormal(20.0, 10.0, 0.0, 60.0);
    const bool retroflexed = retroverted ? rng.bernoulli(0.6) : rng.bernoulli(0.05);
    s.flexionDeg =
        retroflexed ? rng.truncatedNormal(-20.0, 10.0, -50.0, 0.0) : rng.truncatedNormal(22.0, 12.0, -5.0, 55.0);
    s.lateralAsymmetry = std::clamp(rng.normal(0.0, 0.04), -0.12, 0.12);
    s.apAsymmetry = std::clamp(rng.normal(0.0, 0.04), -0.12, 0.12);
    s.cornualHeightAsymmetryMm = std::clamp(rng.normal(0.0, 0.8), -2.5, 2.5);
    s.lengthMm = s.cervixLengthMm + s.cavityLengthMm + s.fundalWallMm;
    return s;
}

Result<CohortResult> generateCohort(const CohortParams& params, Progress& progress) {
    if (params.size < 10 || params.size > 100000)
        return fail(ErrorCode::InvalidInput,
                    "cohort size " + std::to_string(params.size) + " is outside the supported range [10, 100000]");
    CohortResult result;
    Rng root(params.seed);
    int narrowed = 0;
    {
        ScopedStepTimer timer(result.timings, "cohort");
        result.training.layout = params.layout;
        result.training.reference = uterusTemplate(params.layout);
        for (int i = 0; i < params.size; ++i) {
            HS_TRY(progress.check("cohort generation"));
            // One generator per member: member i does not depend on how many numbers member i-1 drew.
            Rng rng = root.derive(static_cast<std::uint64_t>(i));
            CohortMember member;
            member.patient = samplePatient(rng, &member.menopauseAgeYears);
            member.shape = sampleShape(member.patient, member.menopauseAgeYears, rng);
            UterusShapeParams unposed = member.shape;
            unposed.versionDeg = 0.0;
            auto organ = generateUterus(unposed, params.layout);
            if (!organ)
                return fail(ErrorCode::Internal, "cohort member " + std::to_string(i) + ": " + organ.error().detail);
            narrowed += organ->warnings.empty() ? 0 : 1;
            result.training.shapes.push_back(std::move(organ->mesh.points));
            result.training.patients.push_back(member.patient);
            result.members.push_back(member);
            progress.report("anatomy.cohort", static_cast<double>(i + 1) / params.size);
        }
        result.timings.step("cohort").counts.push_back({"members", params.size});
    }
    result.training.reference.points = result.training.shapes.front();
    if (narrowed > 0) {
        std::ostringstream out;
        out << narrowed << " of " << params.size << " cavities were narrowed to keep the minimum wall";
        result.warnings.push_back(out.str());
    }
    return result;
}

} // namespace hs::anatomy
