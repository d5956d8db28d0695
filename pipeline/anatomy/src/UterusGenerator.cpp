#include "hs/anatomy/UterusGenerator.h"

#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hs::anatomy {

namespace {

constexpr double kDomeExponent = 2.6;    ///< superellipse exponent of the fundal dome: broad, flat fundus
constexpr double kLowerExponent = 2.0;   ///< the corpus narrows elliptically towards the isthmus
constexpr double kOuterSectionExp = 2.2; ///< cross-section of the serosa: slightly fuller than an ellipse
constexpr double kBlendPower = 8.0;      ///< soft maximum joining corpus and cervix at the isthmus
constexpr double kPortioShrink = 0.82;   ///< the portio rounds off to this fraction of the cervix radius at the os
constexpr double kMinBendLengthMm = 20.0;
constexpr double kWallWindowMm = 7.0; ///< mm; half-height of the window in which the wall rule looks at the serosa
// kOpenCanalHalfWidthMm (UterusGenerator.h): the canal is at least 4 mm across in every direction. In life it is
// collapsed at rest and the scope opens it (Nott et al. 2016: "outside of pregnancy the cervical canal is
// collapsed"); the scene is the rest state a simulator starts from, so it keeps the way open for the thinnest office
// hysteroscope (2.9 mm), with about 0.5 mm each side for what meshing takes off a narrow canal (docs/anatomy.md,
// "Open canal"). 4 mm is also the narrowest internal os of Chen et al.'s 95 % range (4-11 mm; docs/references.md
// [Chen2020]).

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// Signed power keeping the sign of `v`: the superellipse parametrisation.
double spow(double v, double e) {
    return v < 0.0 ? -std::pow(-v, e) : std::pow(v, e);
}

struct Range {
    const char* name;
    double value, lo, hi;
    const char* unit;
};

Status checkControls(const UterusShapeParams& p) {
    const Range ranges[] = {
        {"lengthMm", p.lengthMm, 25.0, 120.0, "mm"},
        {"widthMm", p.widthMm, 15.0, 80.0, "mm"},
        {"apDepthMm", p.apDepthMm, 12.0, 80.0, "mm"},
        {"fundalWallMm", p.fundalWallMm, 5.0, 30.0, "mm"},
        {"cavityLengthMm", p.cavityLengthMm, 5.0, 60.0, "mm"},
        {"cavityWidthMm", p.cavityWidthMm, 4.0, 60.0, "mm"},
        {"cavityDepthMm", p.cavityDepthMm, 1.0, 25.0, "mm"},
        {"cornualAngleDeg", p.cornualAngleDeg, 20.0, 100.0, "degree"},
        {"internalOsWidthMm", p.internalOsWidthMm, 1.5, 15.0, "mm"},
        {"cervixLengthMm", p.cervixLengthMm, 10.0, 60.0, "mm"},
        {"cervixDiameterMm", p.cervixDiameterMm, 12.0, 50.0, "mm"},
        {"versionDeg", p.versionDeg, -90.0, 90.0, "degree"},
        {"flexionDeg", p.flexionDeg, -75.0, 75.0, "degree"},
        {"lateralAsymmetry", p.lateralAsymmetry, -0.3, 0.3, ""},
        {"apAsymmetry", p.apAsymmetry, -0.3, 0.3, ""},
        {"cornualHeightAsymmetryMm", p.cornualHeightAsymmetryMm, -6.0, 6.0, "mm"},
    };
    for (const auto& r : ranges) {
        if (!(std::isfinite(r.value) && r.value >= r.lo && r.value <= r.hi)) {
            std::ostringstream out;
            out << "uterus control " << r.name << " = " << r.value << " is outside [" << r.lo << ", " << r.hi << "] "
                << r.unit;
            return fail(ErrorCode::InvalidInput, out.str());
        }
    }
    const double canal = p.lengthMm - p.fundalWallMm - p.cavityLengthMm;
    if (canal < 8.0) {
        std::ostringstream out;
        out << "uterus controls leave " << canal
            << " mm for the cervical canal (lengthMm - fundalWallMm - cavityLengthMm must be >= 8 mm)";
        return fail(ErrorCode::InvalidInput, out.str());
    }
    return {};
}

Status checkLayout(const TemplateLayout& l) {
    if (l.around < 16 || l.around % 4 != 0 || l.outerRings < 9 || l.osRings < 1 || l.canalRings < 4 ||
        l.cavityRings < 4 || l.capRings < 2)
        return fail(ErrorCode::InvalidInput, "template layout: around must be a multiple of 4 and >= 16, outerRings "
                                             ">= 9, osRings >= 1, canalRings >= 4, cavityRings >= 4, capRings >= 2");
    return {};
}

/// Axial profile of the serosa in the unbent frame (z up the organ axis, external os at z = 0).
struct OuterProfile {
    double length, halfWidth, halfDepth, cervixRadius, cervixLength;
    double widest; ///< z of the widest cross-section
    double bottom; ///< z where the lower corpus ellipse ends (inside the cervix)

    /// Radial factor of the corpus in [0, 1] at height z.
    double corpusFactor(double z) const {
        if (z >= widest) {
            const double t = std::clamp((z - widest) / (length - widest), 0.0, 1.0);
            return std::pow(std::max(0.0, 1.0 - std::pow(t, kDomeExponent)), 1.0 / kDomeExponent);
        }
        const double t = (widest - z) / (widest - bottom);
        return t >= 1.0 ? 0.0 : std::pow(1.0 - std::pow(t, kLowerExponent), 1.0 / kLowerExponent);
    }
    /// The cervix's contribution: rounded at the portio, fading out below the widest section.
    double cervixTerm(double z) const {
        const double portio = kPortioShrink + (1.0 - kPortioShrink) * smoothstep(0.0, 8.0, z);
        const double fade = 1.0 - smoothstep(cervixLength + 5.0, widest, z);
        return cervixRadius * portio * fade;
    }
    double blend(double corpus, double cervix) const {
        return std::pow(std::pow(corpus, kBlendPower) + std::pow(cervix, kBlendPower), 1.0 / kBlendPower);
    }
    double a(double z) const { return blend(halfWidth * corpusFactor(z), cervixTerm(z)); }
    double b(double z) const { return blend(halfDepth * corpusFactor(z), cervixTerm(z)); }
};

/// One ring in the unbent frame: centre on the axis at height z, superellipse half-axes per side.
struct RingSpec {
    double z = 0.0;
    double right = 0.0, left = 0.0, anterior = 0.0, posterior = 0.0;
    double exponent = 2.0;
    double cornualLift = 0.0; ///< mm; z offset of the +x side, the -x side gets the negative
};

Vec3 ringPoint(const RingSpec& r, double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    const double e = 2.0 / r.exponent;
    const double x = (c >= 0.0 ? r.right : r.left) * spow(c, e);
    const double y = (s >= 0.0 ? r.anterior : r.posterior) * spow(s, e);
    const double lift = r.cornualLift * spow(c, 4.0);
    return {x, y, r.z + lift};
}

/// Bends the unbent organ at the isthmus (flexion) and tilts it about the external os (version).
struct Bender {
    double start = 0.0, length = 1.0, angle = 0.0; ///< bend region [start, start + length] mm, angle rad
    double version = 0.0;                          ///< rad

    /// Centreline point and tangent angle at unbent height z.
    void centre(double z, Vec3& c, double& psi) const {
        if (z <= start || std::abs(angle) < 1e-9) {
            c = {0.0, 0.0, z};
            psi = 0.0;
            return;
        }
        const double u = std::min(z - start, length) / length;
        psi = angle * u;
        // Arc of radius length/angle, written without dividing by a small angle.
        const double sinc = std::sin(psi) / angle;
        const double versine = (1.0 - std::cos(psi)) / angle;
        c = {0.0, length * versine, start + length * sinc};
        if (z > start + length)
            c += Vec3{0.0, std::sin(angle), std::cos(angle)} * (z - start - length);
    }
    Vec3 map(const Vec3& local, double zAxis) const {
        Vec3 c;
        double psi = 0.0;
        centre(zAxis, c, psi);
        // Positive flexion turns +z towards +y (anterior): the section's y axis turns towards -z.
        const Vec3 yAxis{0.0, std::cos(psi), -std::sin(psi)};
        const Vec3 p =
            c + Vec3{local.x, 0.0, 0.0} + yAxis * local.y + Vec3{0.0, std::sin(psi), std::cos(psi)} * (local.z - zAxis);
        const double cv = std::cos(version), sv = std::sin(version);
        return {p.x, p.y * cv + p.z * sv, -p.y * sv + p.z * cv};
    }
};

struct Builder {
    const UterusShapeParams& p;
    const TemplateLayout& layout;
    OuterProfile outer{};
    double internalOs = 0.0, cavityTop = 0.0, capHeight = 0.0;
    double narrowedMm = 0.0; ///< largest narrowing of the cavity or canal by the wall rule
    std::vector<RingSpec> rings;

    void setUp() {
        const double L = p.lengthMm;
        internalOs = L - p.fundalWallMm - p.cavityLengthMm;
        cavityTop = L - p.fundalWallMm;
        capHeight = std::min(4.0, 0.15 * p.cavityLengthMm);
        outer.length = L;
        outer.halfWidth = 0.5 * p.widthMm;
        outer.halfDepth = 0.5 * p.apDepthMm;
        outer.cervixRadius = 0.5 * p.cervixDiameterMm;
        outer.cervixLength = std::min(p.cervixLengthMm, L - 12.0);
        // The corpus is widest at the level of the cornua, never lower than halfway up the corpus.
        const double mid = outer.cervixLength + 0.5 * (L - outer.cervixLength);
        outer.widest = std::min(std::max(mid, cavityTop - capHeight - 2.0), L - 6.0);
        outer.bottom = std::min(0.55 * outer.cervixLength, outer.widest - 5.0);
    }

    double sideScale(double asymmetry) const { return 1.0 - std::abs(asymmetry); }

    RingSpec outerRing(double z, double factorOverride = -1.0) const {
        RingSpec r;
        r.z = z;
        double a = outer.a(z), b = outer.b(z);
        if (factorOverride >= 0.0) {
            a = outer.halfWidth * factorOverride;
            b = outer.halfDepth * factorOverride;
        }
        r.right = a * (1.0 + p.lateralAsymmetry);
        r.left = a * (1.0 - p.lateralAsymmetry);
        r.anterior = b * (1.0 + p.apAsymmetry);
        r.posterior = b * (1.0 - p.apAsymmetry);
        r.exponent = kOuterSectionExp;
        return r;
    }
    /// Largest inner half-width and half-depth at height z that keep the minimum wall.
    /// The serosa's half-axis over a window around z: where it curves (dome, portio) the wall must also be thick
    /// enough diagonally, not only in the cross-section.
    template <class F>
    double windowMin(double z, F f) const {
        double m = 1e300;
        for (double dz = -kWallWindowMm; dz <= kWallWindowMm; dz += 1.0)
            m = std::min(m, f(std::clamp(z + dz, 0.0, outer.length)));
        return m;
    }
    double maxInnerA(double z) const {
        return windowMin(z, [&](double t) { return outer.a(t); }) * sideScale(p.lateralAsymmetry) - kMinimumWallMm;
    }
    double maxInnerB(double z) const {
        return windowMin(z, [&](double t) { return outer.b(t); }) * sideScale(p.apAsymmetry) - kMinimumWallMm;
    }

    RingSpec innerRing(double z, double a, double b, double lift) {
        const double ca = std::max(0.5, std::min(a, maxInnerA(z)));
        const double cb = std::max(0.5, std::min(b, maxInnerB(z)));
        narrowedMm = std::max({narrowedMm, a - ca, b - cb});
        RingSpec r;
        r.z = z;
        r.right = r.left = ca;
        r.anterior = r.posterior = cb;
        r.cornualLift = lift;
        return r;
    }

    void addOuterRings() {
        const int dome = layout.outerRings / 3;
        const int body = layout.outerRings - dome;
        const double domeHeight = outer.length - outer.widest;
        for (int k = 0; k < dome; ++k) {
            const double beta = 0.5 * units::kPi * (k + 1) / dome;
            const double z = outer.widest + domeHeight * std::pow(std::cos(beta), 2.0 / kDomeExponent);
            const double r = std::pow(std::sin(beta), 2.0 / kDomeExponent);
            // Blend with the profile so that the dome meets the body rings without a kink.
            RingSpec ring = outerRing(z, r);
            rings.push_back(ring);
        }
        for (int k = 1; k <= body; ++k)
            rings.push_back(outerRing(outer.widest * (1.0 - static_cast<double>(k) / body)));
    }

    void addCanalRings() {
        const double rio = 0.5 * p.internalOsWidthMm;
        const double rext = std::max(1.5, 0.55 * rio);
        for (int k = 0; k < layout.canalRings; ++k) {
            const double u = static_cast<double>(k) / (layout.canalRings - 1);
            const double z = internalOs * u;
            // Fusiform canal: narrow at both ora, widest in the middle; never narrower than the open canal.
            const double r = rext + (rio - rext) * u + 0.25 * rio * std::sin(units::kPi * u);
            rings.push_back(
                innerRing(z, std::max(r, kOpenCanalHalfWidthMm), std::max(0.8 * r, kOpenCanalHalfWidthMm), 0.0));
        }
    }

    double cavityExponent(double height, double rio) const {
        // The lateral wall c(s) = rio + (w/2 - rio) s^g meets the intercornual line at the cornual angle:
        // tan(angle) = height / ((w/2 - rio) g).
        const double spread = std::max(0.5, 0.5 * p.cavityWidthMm - rio);
        const double g = height / (spread * std::tan(units::degToRad(std::min(p.cornualAngleDeg, 89.0))));
        return std::clamp(g, 0.35, 3.0);
    }

    void addCavityRings() {
        const double rio = std::max(0.5 * p.internalOsWidthMm, kOpenCanalHalfWidthMm);
        const double dio = std::max(0.8 * rio, kOpenCanalHalfWidthMm);
        const double halfWidth = std::max(rio, 0.5 * p.cavityWidthMm);
        const double halfDepth = std::max(dio, 0.5 * p.cavityDepthMm);
        const double top = cavityTop - capHeight;
        const double g = cavityExponent(top - internalOs, rio);
        for (int k = 1; k <= layout.cavityRings; ++k) {
            const double s = static_cast<double>(k) / layout.cavityRings;
            const double z = internalOs + s * (top - internalOs);
            const double c = rio + (halfWidth - rio) * std::pow(s, g);
            const double d = dio + (halfDepth - dio) * (1.0 - (1.0 - s) * (1.0 - s));
            rings.push_back(innerRing(z, c, d, 0.5 * p.cornualHeightAsymmetryMm * s * s));
        }
        // Cap: a flat dome from the cornua to the fundal midline. Its half-axes are limited at every cap height.
        const RingSpec equator = rings.back();
        for (int k = 1; k <= layout.capRings; ++k) {
            const double alpha = 0.5 * units::kPi * (1.0 - static_cast<double>(k) / (layout.capRings + 1));
            const double z = top + capHeight * std::cos(alpha);
            const double r = std::sin(alpha);
            rings.push_back(innerRing(z, equator.right * r, equator.anterior * r, 0.5 * p.cornualHeightAsymmetryMm));
        }
    }
};

void addTopology(SurfaceMesh& mesh, const TemplateLayout& l) {
    const int m = l.around;
    const int rings = l.ringCount();
    mesh.triangles.reserve(static_cast<std::size_t>(l.faceCount()));
    std::vector<std::int32_t> tissue;
    tissue.reserve(static_cast<std::size_t>(l.faceCount()));
    auto bandTissue = [&](int band) {
        if (band <= l.outerRings - 2)
            return clinical::SurfaceTissue::Serosa;
        if (band < l.firstCanalRing())
            return clinical::SurfaceTissue::Ectocervix;
        if (band < l.internalOsRing())
            return clinical::SurfaceTissue::CervicalCanal;
        return clinical::SurfaceTissue::Endometrium;
    };
    auto isOstial = [&](int ring, int j) {
        if (ring < l.lastCavityRing() - 1 || ring > l.lastCavityRing() + 1)
            return false;
        const int jj = ((j % m) + m) % m;
        const int half = m / 2;
        return jj <= 1 || jj >= m - 1 || std::abs(jj - half) <= 1;
    };
    auto push = [&](int a, int b, int c, clinical::SurfaceTissue t) {
        mesh.triangles.push_back({a, b, c});
        tissue.push_back(clinical::labelValue(t));
    };
    for (int j = 0; j < m; ++j)
        push(0, l.vertex(0, j), l.vertex(0, j + 1), clinical::SurfaceTissue::Serosa);
    for (int band = 0; band < rings - 1; ++band) {
        const clinical::SurfaceTissue t = bandTissue(band);
        for (int j = 0; j < m; ++j) {
            const int a = l.vertex(band, j), b = l.vertex(band + 1, j);
            const int c = l.vertex(band + 1, j + 1), d = l.vertex(band, j + 1);
            const bool ostium =
                isOstial(band, j) && isOstial(band + 1, j) && isOstial(band, j + 1) && isOstial(band + 1, j + 1);
            push(a, b, c, ostium ? clinical::SurfaceTissue::TubalOstium : t);
            push(a, c, d, ostium ? clinical::SurfaceTissue::TubalOstium : t);
        }
    }
    for (int j = 0; j < m; ++j)
        push(l.vertex(rings - 1, j), l.innerPole(), l.vertex(rings - 1, j + 1), clinical::SurfaceTissue::Endometrium);
    mesh.faceLabels[clinical::kSurfaceTissueLabel] = std::move(tissue);
}

} // namespace

double openPassage(SurfaceMesh& mesh, const TemplateLayout& l) {
    if (mesh.points.size() != static_cast<std::size_t>(l.vertexCount()))
        return 0.0;
    auto point = [&](int ring, int j) -> Vec3& { return mesh.points[static_cast<std::size_t>(l.vertex(ring, j))]; };
    auto centroid = [&](int ring) {
        Vec3 c;
        for (int j = 0; j < l.around; ++j)
            c += point(ring, j);
        return c / l.around;
    };
    std::vector<Vec3> centres;
    for (int r = l.firstCanalRing() - 1; r <= l.lastCavityRing() + 1; ++r)
        centres.push_back(centroid(r));
    double moved = 0.0;
    for (int r = l.firstCanalRing(); r <= l.lastCavityRing(); ++r) {
        const auto k = static_cast<std::size_t>(r - l.firstCanalRing() + 1);
        const Vec3 c = centres[k];
        // The ring's plane: normal to the passage's centreline through it (the rings of a bent organ tilt with it).
        const Vec3 along = normalized(centres[k + 1] - centres[k - 1]);
        for (int j = 0; j < l.around; ++j) {
            Vec3& p = point(r, j);
            const Vec3 d = p - c;
            const Vec3 inPlane = d - along * dot(d, along);
            const double rho = norm(inPlane);
            if (rho >= kOpenCanalHalfWidthMm || rho < 1e-9)
                continue;
            p += inPlane * ((kOpenCanalHalfWidthMm - rho) / rho);
            moved = std::max(moved, kOpenCanalHalfWidthMm - rho);
        }
    }
    return moved;
}

SurfaceMesh uterusTemplate(const TemplateLayout& layout) {
    SurfaceMesh mesh;
    mesh.points.assign(static_cast<std::size_t>(layout.vertexCount()), Vec3{});
    addTopology(mesh, layout);
    return mesh;
}

Result<UterusResult> generateUterus(const UterusShapeParams& params, const TemplateLayout& layout) {
    HS_TRY(checkControls(params));
    HS_TRY(checkLayout(layout));

    Builder builder{params, layout, {}, 0.0, 0.0, 0.0, 0.0, {}};
    builder.setUp();
    builder.addOuterRings();
    const RingSpec osOuter = builder.rings.back();
    const std::size_t osRingsAt = builder.rings.size();
    builder.rings.resize(builder.rings.size() + static_cast<std::size_t>(layout.osRings)); // filled below
    builder.addCanalRings();
    const RingSpec osInner = builder.rings[osRingsAt + static_cast<std::size_t>(layout.osRings)];
    builder.addCavityRings();

    // Bend: centred at the internal os, long enough that the concave side of the wall cannot fold.
    Bender bender;
    bender.angle = units::degToRad(params.flexionDeg);
    bender.version = units::degToRad(params.versionDeg);
    double depth = 0.0;
    for (double z = builder.internalOs - 25.0; z <= builder.internalOs + 25.0; z += 1.0)
        depth = std::max(depth, builder.outer.b(z) * (1.0 + std::abs(params.apAsymmetry)));
    bender.length = std::max(kMinBendLengthMm, 1.8 * depth * std::abs(bender.angle));
    bender.start = std::max(2.0, builder.internalOs - 0.5 * bender.length);

    UterusResult result;
    result.layout = layout;
    SurfaceMesh& mesh = result.mesh;
    mesh.points.resize(static_cast<std::size_t>(layout.vertexCount()));
    const int m = layout.around;
    mesh.points[0] = bender.map({0.0, 0.0, params.lengthMm}, params.lengthMm);
    for (int r = 0; r < layout.ringCount(); ++r) {
        const bool rim = r >= layout.outerRings && r < layout.firstCanalRing();
        for (int j = 0; j < m; ++j) {
            const double phi = 2.0 * units::kPi * j / m;
            Vec3 local;
            if (rim) {
                // Ectocervix: from the portio's edge inwards to the external os, bulging slightly outwards.
                const double s = static_cast<double>(r - layout.outerRings + 1) / (layout.osRings + 1);
                local = ringPoint(osOuter, phi) * (1.0 - s) + ringPoint(osInner, phi) * s;
                local.z -= 1.5 * std::sin(units::kPi * s);
            } else {
                local = ringPoint(builder.rings[static_cast<std::size_t>(r)], phi);
            }
            mesh.points[static_cast<std::size_t>(layout.vertex(r, j))] =
                bender.map(local, rim ? 0.0 : builder.rings[static_cast<std::size_t>(r)].z);
        }
    }
    mesh.points[static_cast<std::size_t>(layout.innerPole())] =
        bender.map({0.0, 0.0, builder.cavityTop}, builder.cavityTop);
    addTopology(mesh, layout);

    if (builder.narrowedMm > 0.5) {
        std::ostringstream out;
        out.precision(3);
        out << "cavity or canal narrowed by up to " << builder.narrowedMm << " mm to keep a wall of " << kMinimumWallMm
            << " mm";
        result.warnings.push_back(out.str());
    }
    return result;
}

} // namespace hs::anatomy
