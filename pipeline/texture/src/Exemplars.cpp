// Procedural default exemplars. Colours are chosen after published hysteroscopic descriptions: the normal
// endometrium is pink to red with punctate glandular openings; a submucous myoma is paler, whitish, with
// larger, regular surface vessels; a polyp is smooth, glossy, pink (e.g. Bettocchi et al., "Operative office
// hysteroscopy", 2004; van Dongen et al., "Diagnostic hysteroscopy and saline infusion sonography", 2008); the
// endocervix is whitish pink, thrown into papillae between clefts, with fine branched vessels (Mhaskar, "Hysteroscopy",
// chapter 1; docs/texture.md, "The cervical canal").
#include "hs/texture/Exemplars.h"

#include "hs/core/Rng.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hs::texture {
namespace {

struct Rgb {
    double r, g, b;
};

Rgb mix(const Rgb& a, const Rgb& b, double t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

/// Periodic value noise on a lattice of `cells` x `cells`, smooth (quintic) interpolation; values in [-1, 1].
class ValueNoise {
public:
    ValueNoise(int cells, Rng& rng) : m_cells(cells), m_values(static_cast<std::size_t>(cells * cells)) {
        for (auto& v : m_values)
            v = rng.uniform(-1.0, 1.0);
    }
    /// x, y in [0, 1): one period.
    double operator()(double x, double y) const {
        const double fx = x * m_cells;
        const double fy = y * m_cells;
        const int ix = static_cast<int>(std::floor(fx));
        const int iy = static_cast<int>(std::floor(fy));
        const double tx = fade(fx - ix);
        const double ty = fade(fy - iy);
        const double a = at(ix, iy), b = at(ix + 1, iy), c = at(ix, iy + 1), d = at(ix + 1, iy + 1);
        return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
    }

private:
    static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
    double at(int x, int y) const {
        x = ((x % m_cells) + m_cells) % m_cells;
        y = ((y % m_cells) + m_cells) % m_cells;
        return m_values[static_cast<std::size_t>(y * m_cells + x)];
    }
    int m_cells;
    std::vector<double> m_values;
};

/// Sum of octaves of periodic value noise, roughly in [-1, 1].
class Fbm {
public:
    Fbm(int baseCells, int octaves, Rng& rng) {
        for (int o = 0; o < octaves; ++o)
            m_octaves.emplace_back(baseCells << o, rng);
    }
    double operator()(double x, double y) const {
        double sum = 0.0, amp = 1.0, norm = 0.0;
        for (const auto& n : m_octaves) {
            sum += amp * n(x, y);
            norm += amp;
            amp *= 0.5;
        }
        return sum / norm;
    }

private:
    std::vector<ValueNoise> m_octaves;
};

class Canvas {
public:
    explicit Canvas(int size) : m_size(size), m_px(static_cast<std::size_t>(size * size), Rgb{0, 0, 0}) {}
    int size() const { return m_size; }
    Rgb& at(int x, int y) {
        x = ((x % m_size) + m_size) % m_size;
        y = ((y % m_size) + m_size) % m_size;
        return m_px[static_cast<std::size_t>(y * m_size + x)];
    }
    /// Blends `colour` into a soft disc (periodic), coverage 1 inside radius, fading over one pixel.
    void disc(double cx, double cy, double radius, const Rgb& colour, double opacity) {
        const int r = static_cast<int>(std::ceil(radius + 1.0));
        for (int y = static_cast<int>(std::floor(cy)) - r; y <= static_cast<int>(std::floor(cy)) + r; ++y)
            for (int x = static_cast<int>(std::floor(cx)) - r; x <= static_cast<int>(std::floor(cx)) + r; ++x) {
                const double d = std::sqrt((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy));
                const double cover = std::clamp(radius + 0.5 - d, 0.0, 1.0) * opacity;
                if (cover > 0.0)
                    at(x, y) = mix(at(x, y), colour, cover);
            }
    }
    void blur3() {
        std::vector<Rgb> copy = m_px;
        for (int y = 0; y < m_size; ++y)
            for (int x = 0; x < m_size; ++x) {
                Rgb sum{0, 0, 0};
                double wsum = 0.0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const double w = (dx == 0 ? 2.0 : 1.0) * (dy == 0 ? 2.0 : 1.0);
                        const int xx = (x + dx + m_size) % m_size, yy = (y + dy + m_size) % m_size;
                        const Rgb& p = copy[static_cast<std::size_t>(yy * m_size + xx)];
                        sum = {sum.r + w * p.r, sum.g + w * p.g, sum.b + w * p.b};
                        wsum += w;
                    }
                m_px[static_cast<std::size_t>(y * m_size + x)] = {sum.r / wsum, sum.g / wsum, sum.b / wsum};
            }
    }
    ImageU8 toImage() const {
        auto image = ImageU8::create(m_size, m_size, 3).value();
        auto& d = image.data();
        for (std::size_t i = 0; i < m_px.size(); ++i) {
            d[i * 3 + 0] = toByte(m_px[i].r);
            d[i * 3 + 1] = toByte(m_px[i].g);
            d[i * 3 + 2] = toByte(m_px[i].b);
        }
        return image;
    }

private:
    static std::uint8_t toByte(double v) {
        return static_cast<std::uint8_t>(std::clamp(std::lround(v * 255.0), 0L, 255L));
    }
    int m_size;
    std::vector<Rgb> m_px;
};

/// A thin vessel as a random walk with inertia, drawn as overlapping soft discs.
void drawVessel(Canvas& canvas, Rng& rng, double radius, const Rgb& colour, double opacity, double length) {
    double x = rng.uniform(0, canvas.size()), y = rng.uniform(0, canvas.size());
    double angle = rng.uniform(0, 6.283185307179586);
    double turn = 0.0;
    for (double s = 0; s < length; s += 0.5) {
        canvas.disc(x, y, radius, colour, opacity);
        turn = 0.9 * turn + 0.06 * rng.uniform(-1.0, 1.0);
        angle += turn;
        x += 0.5 * std::cos(angle);
        y += 0.5 * std::sin(angle);
        if (radius > 0.6 && rng.bernoulli(0.004)) // a side branch
            drawVessel(canvas, rng, radius * 0.7, colour, opacity, length * 0.4);
    }
}

/// The endometrium's palette and marks per state.
struct EndometriumLook {
    Rgb deep, pink, pale; ///< the mucosa's darker and lighter tones, and the gland openings'
    double lowAmplitude;  ///< the large blotches' contrast
    double glandsPer;     ///< one gland opening per this many pixels (at any size)
    double glandScale;    ///< the openings' size, relative to the proliferative's (0.7-1.5 px at 256)
    double shedding;      ///< 0..1: share of dark haemorrhagic patches (menstrual)
    int petechiae;        ///< small dark red dots per 256 x 256
};

EndometriumLook endometriumLook(EndometrialState state) {
    switch (state) {
    case EndometrialState::Secretory: // pale pink, yellowish; larger, open glands
        return {{0.80, 0.40, 0.34}, {0.93, 0.62, 0.52}, {0.97, 0.84, 0.70}, 0.35, 110.0, 1.5, 0.0, 0};
    case EndometrialState::Menstrual: // reddish to dark red, shedding and bleeding
        return {{0.42, 0.07, 0.08}, {0.72, 0.22, 0.22}, {0.80, 0.45, 0.42}, 0.45, 260.0, 0.9, 0.45, 0};
    case EndometrialState::Atrophic: // thin, pale, smooth; petechiae; few glands
        return {{0.82, 0.52, 0.50}, {0.94, 0.76, 0.70}, {0.97, 0.88, 0.82}, 0.25, 900.0, 0.7, 0.0, 40};
    case EndometrialState::Proliferative:
        break;
    }
    return {{0.62, 0.18, 0.20}, {0.86, 0.42, 0.42}, {0.93, 0.66, 0.62}, 0.45, 150.0, 1.0, 0.0, 0};
}

ImageU8 endometrium(int size, Rng& rng, EndometrialState state) {
    Canvas canvas(size);
    const EndometriumLook look = endometriumLook(state);
    const Fbm low(4, 3, rng), grain(size / 8, 2, rng), blotch(size / 24, 2, rng);
    const Rgb deep = look.deep, pink = look.pink, pale = look.pale;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            const double t = std::clamp(0.5 + look.lowAmplitude * low(u, v) + 0.2 * blotch(u, v), 0.0, 1.0);
            Rgb c = mix(deep, pink, t);
            const double g = 0.06 * grain(u, v);
            c = {c.r + g, c.g + 0.7 * g, c.b + 0.7 * g};
            canvas.at(x, y) = c;
        }
    // Glandular openings: small pale dots with a darker rim (proliferative: about one per 12x12 pixels at 256).
    const int glands = static_cast<int>(size * size / look.glandsPer);
    for (int i = 0; i < glands; ++i) {
        const double x = rng.uniform(0, size), y = rng.uniform(0, size);
        const double r = rng.uniform(0.7, 1.5) * look.glandScale * size / 256.0;
        canvas.disc(x, y, r * 1.9, deep, 0.35);
        canvas.disc(x, y, r, pale, rng.uniform(0.55, 0.9));
    }
    if (look.shedding > 0.0) {
        // Shedding: dark red patches where the functional layer comes away and bleeds, beside preserved mucosa.
        const Fbm patches(6, 3, rng);
        const Rgb blood{0.30, 0.03, 0.04};
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const double u = (x + 0.5) / size, v = (y + 0.5) / size;
                const double shed = std::clamp((patches(u, v) + 0.25 - look.shedding * 0.5) * -4.0, 0.0, 1.0);
                canvas.at(x, y) = mix(canvas.at(x, y), blood, 0.8 * shed);
            }
    }
    // Petechiae: pinpoint haemorrhages under a thin, atrophic mucosa.
    const Rgb petechia{0.62, 0.08, 0.10};
    const int petechiae = look.petechiae * size * size / (256 * 256);
    for (int i = 0; i < petechiae; ++i)
        canvas.disc(rng.uniform(0, size), rng.uniform(0, size), rng.uniform(1.2, 2.6) * size / 256.0, petechia,
                    rng.uniform(0.6, 0.95));
    canvas.blur3();
    return canvas.toImage();
}

ImageU8 myoma(int size, Rng& rng) {
    Canvas canvas(size);
    const Fbm low(3, 3, rng), fibre(size / 16, 2, rng), warp(4, 2, rng);
    const Rgb white{0.93, 0.84, 0.80}, flesh{0.86, 0.64, 0.60};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            // Fibres: noise stretched along a slowly turning direction (whorled smooth muscle under the mucosa).
            const double a = 1.2 * warp(u, v);
            const double fu = u * std::cos(a) - v * std::sin(a), fv = u * std::sin(a) + v * std::cos(a);
            const double f = fibre(fu * 0.25 - std::floor(fu * 0.25), fv - std::floor(fv));
            const double t = std::clamp(0.5 + 0.4 * low(u, v) + 0.25 * f, 0.0, 1.0);
            canvas.at(x, y) = mix(white, flesh, t);
        }
    const Rgb vessel{0.70, 0.16, 0.17};
    const int vessels = std::max(2, size / 64);
    for (int i = 0; i < vessels; ++i)
        drawVessel(canvas, rng, rng.uniform(0.5, 1.1) * size / 256.0, vessel, 0.55, size * 0.8);
    canvas.blur3();
    return canvas.toImage();
}

ImageU8 polyp(int size, Rng& rng) {
    Canvas canvas(size);
    const Fbm low(3, 2, rng), fine(size / 16, 2, rng);
    const Rgb rose{0.90, 0.52, 0.52}, light{0.96, 0.70, 0.68};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            const double t = std::clamp(0.5 + 0.5 * low(u, v) + 0.05 * fine(u, v), 0.0, 1.0);
            canvas.at(x, y) = mix(rose, light, t);
        }
    // Sparse, faint glandular openings: polyps are covered by endometrium, but smoother.
    const int glands = size * size / 900;
    for (int i = 0; i < glands; ++i)
        canvas.disc(rng.uniform(0, size), rng.uniform(0, size), rng.uniform(0.6, 1.1) * size / 256.0, light, 0.5);
    canvas.blur3();
    canvas.blur3();
    return canvas.toImage();
}

/// The endocervical mucosa: whitish pink, papillae crowded between narrow darker clefts (the folds themselves are the
/// bake's relief, drawn from the canal's frame; the vessels are grown on the surface).
ImageU8 endocervix(int size, Rng& rng) {
    Canvas canvas(size);
    const Fbm low(3, 3, rng), clefts(std::max(1, size / 16), 2, rng), grain(size / 8, 2, rng);
    const Rgb rose{0.84, 0.46, 0.46}, white{0.94, 0.74, 0.72}, cleft{0.64, 0.26, 0.29};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            const double t = std::clamp(0.45 + 0.35 * low(u, v) + 0.05 * grain(u, v), 0.0, 1.0);
            Rgb c = mix(rose, white, t);
            // Clefts: the noise's zero crossings, a network of narrow furrows between the papillae.
            const double furrow = std::clamp(1.0 - std::abs(clefts(u, v)) * 6.0, 0.0, 1.0);
            c = mix(c, cleft, 0.5 * furrow * furrow);
            canvas.at(x, y) = c;
        }
    // Papillae: small pale rounded tips, densely packed (about one per 6 x 6 pixels at 256).
    const int papillae = size * size / 36;
    for (int i = 0; i < papillae; ++i)
        canvas.disc(rng.uniform(0, size), rng.uniform(0, size), rng.uniform(1.0, 2.0) * size / 256.0, white,
                    rng.uniform(0.2, 0.45));
    canvas.blur3();
    return canvas.toImage();
}

} // namespace

std::string appearanceName(Appearance appearance) {
    switch (appearance) {
    case Appearance::Endometrium:
        return "endometrium";
    case Appearance::Myoma:
        return "myoma";
    case Appearance::Polyp:
        return "polyp";
    case Appearance::CervicalCanal:
        return "cervical-canal";
    }
    return "unknown";
}

std::string endometrialStateName(EndometrialState state) {
    switch (state) {
    case EndometrialState::Proliferative:
        return "proliferative";
    case EndometrialState::Secretory:
        return "secretory";
    case EndometrialState::Menstrual:
        return "menstrual";
    case EndometrialState::Atrophic:
        return "atrophic";
    }
    return "unknown";
}

EndometrialSurface endometrialSurface(EndometrialState state) {
    switch (state) {
    case EndometrialState::Secretory: // the surface vessels disappear under the stromal oedema; the surface is wavy
        return {0.35, 1.8};
    case EndometrialState::Menstrual: // indentations where the layer sheds
        return {1.0, 1.5};
    case EndometrialState::Atrophic: // thin and smooth, the vessels show through it
        return {1.5, 0.5};
    case EndometrialState::Proliferative:
        break;
    }
    return {1.0, 1.0};
}

Result<ImageU8> makeExemplar(Appearance appearance, int size, std::uint64_t seed, EndometrialState state) {
    if (size < 32 || size > 4096)
        return fail(ErrorCode::LimitExceeded, "exemplar size " + std::to_string(size) + " outside 32..4096 pixels");
    Rng rng = Rng(seed).derive(static_cast<std::uint64_t>(appearance) + 1);
    switch (appearance) {
    case Appearance::Endometrium:
        return endometrium(size, rng, state);
    case Appearance::Myoma:
        return myoma(size, rng);
    case Appearance::Polyp:
        return polyp(size, rng);
    case Appearance::CervicalCanal:
        return endocervix(size, rng);
    }
    return fail(ErrorCode::InvalidInput, "unknown appearance class");
}

} // namespace hs::texture
