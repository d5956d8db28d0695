// Trial files: the device samples of a session with what replays it (Trial.h has the layout).
#include "hs/sim/Trial.h"

#include "TrialJson.h"

#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace hs::sim {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// HSTRIAL2 (written): 80-byte records with the working element and the instrument; HSTRIAL1 (read): 72-byte records of
// the diagnostic scope (working element 0, no instrument).
constexpr char kMagic[8] = {'H', 'S', 'T', 'R', 'I', 'A', 'L', '2'};
constexpr char kMagicV1[8] = {'H', 'S', 'T', 'R', 'I', 'A', 'L', '1'};
constexpr std::string_view kHeaderFormat = "hysteroscene-trial";
constexpr int kHeaderVersion = 2; // 2: the physics that recorded it (engine, step, iterations)
constexpr std::size_t kRecordBytes = 80;
constexpr std::size_t kRecordBytesV1 = 72;
constexpr std::size_t kMaxTextField = 256;
constexpr std::size_t kChunkRecords = 4096; ///< records read or written per chunk (288 kB)

std::string numberText(double v) {
    return scene::formatNumber(v);
}

Error invalid(const std::string& name, const std::string& field, const std::string& what) {
    return Error{ErrorCode::InvalidInput, name + ": " + field + ": " + what};
}

// ---- little-endian encoding, independent of the host's byte order ----

void putU32(std::uint8_t* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void putU64(std::uint8_t* p, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void putF64(std::uint8_t* p, double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    putU64(p, bits);
}
std::uint32_t getU32(const std::uint8_t* p) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
    return v;
}
std::uint64_t getU64(const std::uint8_t* p) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
        v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}
double getF64(const std::uint8_t* p) {
    const std::uint64_t bits = getU64(p);
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

void encodeRecord(const DeviceSample& s, std::uint8_t* p) {
    putU64(p, s.tick);
    const double values[7] = {s.insertionMm, s.pitchDeg, s.yawDeg, s.rollDeg, s.cameraRollDeg, s.inflow, s.outflow};
    for (int i = 0; i < 7; ++i)
        putF64(p + 8 + 8 * i, values[i]);
    putF64(p + 64, s.workingElementMm);
    putU32(p + 72, s.buttons);
    putU32(p + 76, s.instrument);
}

DeviceSample decodeRecord(const std::uint8_t* p, bool v1) {
    DeviceSample s;
    s.tick = getU64(p);
    s.insertionMm = getF64(p + 8);
    s.pitchDeg = getF64(p + 16);
    s.yawDeg = getF64(p + 24);
    s.rollDeg = getF64(p + 32);
    s.cameraRollDeg = getF64(p + 40);
    s.inflow = getF64(p + 48);
    s.outflow = getF64(p + 56);
    if (v1) {
        s.buttons = getU32(p + 64);
        return s;
    }
    s.workingElementMm = getF64(p + 64);
    s.buttons = getU32(p + 72);
    s.instrument = getU32(p + 76);
    return s;
}

/// The first field of `s` outside its range, with the range, or empty when the sample is valid.
std::string sampleProblem(const DeviceSample& s) {
    struct Field {
        const char* name;
        double value, lo, hi;
        const char* unit;
    };
    const Field fields[] = {
        {"insertionMm", s.insertionMm, kMinInsertionMm, kMaxInsertionMm, " mm"},
        {"pitchDeg", s.pitchDeg, -kMaxPivotDeg, kMaxPivotDeg, " degrees"},
        {"yawDeg", s.yawDeg, -kMaxPivotDeg, kMaxPivotDeg, " degrees"},
        {"rollDeg", s.rollDeg, -kMaxRollDeg, kMaxRollDeg, " degrees"},
        {"cameraRollDeg", s.cameraRollDeg, -kMaxRollDeg, kMaxRollDeg, " degrees"},
        {"inflow", s.inflow, 0.0, 1.0, ""},
        {"outflow", s.outflow, 0.0, 1.0, ""},
        {"workingElementMm", s.workingElementMm, 0.0, kMaxWorkingElementMm, " mm"},
    };
    for (const Field& f : fields)
        if (!(std::isfinite(f.value) && f.value >= f.lo && f.value <= f.hi))
            return std::string(f.name) + " " + numberText(f.value) + " is outside " + numberText(f.lo) + ".." +
                   numberText(f.hi) + f.unit;
    if (s.buttons & ~kKnownButtons)
        return "buttons " + std::to_string(s.buttons) + " has bits other than " + std::to_string(kKnownButtons) +
               " (mark, capture, cut, coagulate, pump up, pump down)";
    if (s.instrument > kMaxInstrument)
        return "instrument " + std::to_string(s.instrument) + " is outside 0.." + std::to_string(kMaxInstrument) +
               " (0 none, 1 loop, 2 scissors, 3 grasper)";
    return {};
}

/// Checks sample `index` of `name`: its tick and its fields.
Status checkSample(const DeviceSample& s, std::uint64_t index, const std::string& name) {
    const std::string field = "samples[" + std::to_string(index) + "]";
    if (s.tick != index)
        return invalid(name, field + ".tick",
                       std::to_string(s.tick) + " is not " + std::to_string(index) + " (ticks start at 0, no gaps)");
    const std::string problem = sampleProblem(s);
    if (!problem.empty())
        return invalid(name, field + "." + problem.substr(0, problem.find(' ')), problem);
    return {};
}

bool isLowerHex64(const std::string& text) {
    return text.size() == 64 && std::all_of(text.begin(), text.end(),
                                            [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

std::string headerJson(const TrialHeader& h) {
    ordered_json j;
    j["format"] = kHeaderFormat;
    j["version"] = kHeaderVersion;
    j["sceneSha256"] = h.sceneSha256;
    j["seed"] = h.seed;
    j["physics"] = {
        {"engine", h.physics.engine}, {"stepS", h.physics.stepS}, {"solverIterations", h.physics.solverIterations}};
    j["exercise"] = std::string(toString(h.exercise));
    j["scope"] = {{"opticDeg", h.scope.opticDeg},
                  {"diameterMm", h.scope.diameterMm},
                  {"fieldOfViewDeg", h.scope.fieldOfViewDeg},
                  {"focusNearMm", h.scope.focusNearMm},
                  {"focusFarMm", h.scope.focusFarMm}};
    j["fluid"] = {
        {"pumpPressureKpa", h.fluid.pumpPressureKpa},      {"meanArterialPressureKpa", h.fluid.meanArterialPressureKpa},
        {"deficitWarningMl", h.fluid.deficitWarningMl},    {"deficitLimitMl", h.fluid.deficitLimitMl},
        {"medium", std::string(toString(h.fluid.medium))}, {"elderlyOrComorbid", h.fluid.elderlyOrComorbid}};
    j["device"] = h.device;
    j["startedUtc"] = h.startedUtc;
    return j.dump();
}

void readHeaderFields(const json& document, TrialHeader& h, scene::JsonIssues& issues) {
    scene::ObjectReader root(document, "", issues);
    std::string format;
    root.read("format", format, true);
    if (root.member("format") && format != kHeaderFormat)
        issues.push_back({"/format", scene::quoteText(format) + " is not \"" + std::string(kHeaderFormat) + "\""});
    int version = 0;
    root.read("version", version, true);
    if (root.member("version") && version != kHeaderVersion)
        issues.push_back({"/version", std::to_string(version) + " is not the version this build reads (" +
                                          std::to_string(kHeaderVersion) + ")"});
    detail::readHeaderMembers(root, h);
    root.finish();
}

Result<TrialHeader> parseHeader(const std::string& text, const std::string& name, std::uint32_t maxBytes) {
    scene::JsonDocumentLimits limits;
    limits.maxBytes = maxBytes;
    limits.maxDepth = 4;
    limits.kind = "trial header";
    auto header = scene::parseJsonDocument<TrialHeader>(text, name + ": header", limits, readHeaderFields);
    if (!header)
        return header.failure();
    HS_TRY(detail::checkHeader(*header, name));
    return header;
}

/// Where the bytes of a trial come from: memory or a file read in chunks (a four-hour trial is ~1 GB).
class ByteSource {
public:
    virtual ~ByteSource() = default;
    virtual std::uint64_t remaining() const = 0;
    /// Reads exactly `n` bytes; false when fewer are left or the read fails.
    virtual bool read(void* out, std::size_t n) = 0;
};

class MemorySource final : public ByteSource {
public:
    explicit MemorySource(const std::string& bytes) : m_bytes(bytes) {}
    std::uint64_t remaining() const override { return m_bytes.size() - m_pos; }
    bool read(void* out, std::size_t n) override {
        if (n > m_bytes.size() - m_pos)
            return false;
        std::memcpy(out, m_bytes.data() + m_pos, n);
        m_pos += n;
        return true;
    }

private:
    const std::string& m_bytes;
    std::size_t m_pos = 0;
};

class FileSource final : public ByteSource {
public:
    FileSource(std::FILE* file, std::uint64_t size) : m_file(file), m_left(size) {}
    ~FileSource() override { std::fclose(m_file); }
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;
    std::uint64_t remaining() const override { return m_left; }
    bool read(void* out, std::size_t n) override {
        if (n > m_left || std::fread(out, 1, n, m_file) != n)
            return false;
        m_left -= n;
        return true;
    }

private:
    std::FILE* m_file;
    std::uint64_t m_left;
};

Result<Trial> parseFrom(ByteSource& in, const std::string& name, const TrialReadLimits& limits) {
    const auto truncated = [&](const std::string& field) {
        return invalid(name, field, "the file ends early (truncated)");
    };
    char magic[8] = {};
    if (!in.read(magic, sizeof magic))
        return truncated("magic");
    const bool v1 = std::memcmp(magic, kMagicV1, sizeof magic) == 0;
    if (!v1 && std::memcmp(magic, kMagic, sizeof magic) != 0)
        return invalid(name, "magic", "is not \"HSTRIAL2\" or \"HSTRIAL1\" (not a trial file, or another version)");
    const std::size_t recordBytes = v1 ? kRecordBytesV1 : kRecordBytes;
    std::uint8_t word[8] = {};
    if (!in.read(word, 4))
        return truncated("headerLength");
    const std::uint32_t headerBytes = getU32(word);
    if (headerBytes > limits.maxHeaderBytes)
        return Error{ErrorCode::LimitExceeded, name + ": headerLength: " + std::to_string(headerBytes) +
                                                   " bytes is above the limit of " +
                                                   std::to_string(limits.maxHeaderBytes)};
    if (headerBytes > in.remaining())
        return truncated("header");
    std::string headerText(headerBytes, '\0');
    if (!in.read(headerText.data(), headerBytes))
        return truncated("header");
    auto header = parseHeader(headerText, name, limits.maxHeaderBytes);
    if (!header)
        return header.failure();

    if (!in.read(word, 8))
        return truncated("sampleCount");
    const std::uint64_t count = getU64(word);
    if (count > limits.maxSamples)
        return Error{ErrorCode::LimitExceeded, name + ": sampleCount: " + std::to_string(count) +
                                                   " is above the limit of " + std::to_string(limits.maxSamples) +
                                                   " samples"};
    const std::uint64_t left = in.remaining();
    if (left / recordBytes < count)
        return invalid(name, "sampleCount",
                       std::to_string(count) + " samples need " + std::to_string(count * recordBytes) +
                           " bytes but the file has " + std::to_string(left) + " left (truncated)");
    if (left != count * recordBytes)
        return invalid(name, "sampleCount",
                       std::to_string(left - count * recordBytes) + " bytes after the last of " +
                           std::to_string(count) + " samples");

    Trial trial;
    trial.header = std::move(header).value();
    trial.samples.reserve(static_cast<std::size_t>(count));
    std::vector<std::uint8_t> chunk(kChunkRecords * recordBytes);
    for (std::uint64_t done = 0; done < count;) {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkRecords, count - done));
        if (!in.read(chunk.data(), n * recordBytes))
            return Error{ErrorCode::IoError, name + ": samples: read failed at sample " + std::to_string(done)};
        for (std::size_t i = 0; i < n; ++i, ++done) {
            const std::uint8_t* record = chunk.data() + i * recordBytes;
            const DeviceSample s = decodeRecord(record, v1);
            HS_TRY(checkSample(s, done, name));
            if (v1 && getU32(record + 68) != 0)
                return invalid(name, "samples[" + std::to_string(done) + "].reserved", "must be 0");
            trial.samples.push_back(s);
        }
    }
    return trial;
}

std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

Status writeTo(std::FILE* file, const Trial& trial, const std::string& header, const std::string& path) {
    std::vector<std::uint8_t> head(8 + 4);
    std::memcpy(head.data(), kMagic, 8);
    putU32(head.data() + 8, static_cast<std::uint32_t>(header.size()));
    std::uint8_t count[8];
    putU64(count, trial.samples.size());
    bool ok = std::fwrite(head.data(), 1, head.size(), file) == head.size() &&
              std::fwrite(header.data(), 1, header.size(), file) == header.size() &&
              std::fwrite(count, 1, sizeof count, file) == sizeof count;
    std::vector<std::uint8_t> chunk(kChunkRecords * kRecordBytes);
    for (std::size_t done = 0; ok && done < trial.samples.size();) {
        const std::size_t n = std::min(kChunkRecords, trial.samples.size() - done);
        for (std::size_t i = 0; i < n; ++i)
            encodeRecord(trial.samples[done + i], chunk.data() + i * kRecordBytes);
        ok = std::fwrite(chunk.data(), 1, n * kRecordBytes, file) == n * kRecordBytes;
        done += n;
    }
    const int writeError = errno;
    const bool closed = std::fclose(file) == 0;
    if (!ok || !closed)
        return fail(ErrorCode::IoError, path + ": write failed: " + systemMessage(writeError));
    return {};
}

} // namespace

namespace detail {

Status checkHeader(const TrialHeader& h, const std::string& name) {
    if (!isLowerHex64(h.sceneSha256))
        return invalid(name, "header.sceneSha256", "must be 64 lower-case hex digits (the manifest's SHA-256)");
    if (h.device.size() > kMaxTextField)
        return invalid(name, "header.device", "is longer than " + std::to_string(kMaxTextField) + " bytes");
    if (h.startedUtc.size() > kMaxTextField)
        return invalid(name, "header.startedUtc", "is longer than " + std::to_string(kMaxTextField) + " bytes");
    if (h.physics.engine.empty() || h.physics.engine.size() > kMaxTextField)
        return invalid(name, "header.physics.engine", "must be 1-" + std::to_string(kMaxTextField) + " bytes");
    const double ticks = h.physics.stepS * kDeviceRateHz;
    if (!std::isfinite(h.physics.stepS) || h.physics.stepS < 0.001 || h.physics.stepS > 0.02 ||
        std::abs(ticks - std::round(ticks)) > 1e-9)
        return invalid(name, "header.physics.stepS", "must be 0.001-0.02 s, a whole number of 1 ms device ticks");
    if (h.physics.solverIterations < 1 || h.physics.solverIterations > 50)
        return invalid(name, "header.physics.solverIterations", "must be 1-50");
    if (Status s = checkScopeConfig(h.scope); !s)
        return Error{ErrorCode::InvalidInput, name + ": header." + s.error().detail};
    if (Status s = checkFluidSettings(h.fluid); !s)
        return Error{ErrorCode::InvalidInput, name + ": header." + s.error().detail};
    return {};
}

void readHeaderMembers(scene::ObjectReader& root, TrialHeader& h) {
    scene::JsonIssues& issues = root.issues();
    root.read("sceneSha256", h.sceneSha256, true);
    root.read("seed", h.seed, true);
    if (const json* p = root.member("physics", true)) {
        scene::ObjectReader physics(*p, root.pathOf("physics"), issues);
        physics.read("engine", h.physics.engine, true);
        physics.read("stepS", h.physics.stepS, true);
        physics.read("solverIterations", h.physics.solverIterations, true);
        physics.finish();
    }
    if (const json* e = root.member("exercise", true)) {
        if (!e->is_string() || !fromString(e->get_ref<const std::string&>(), h.exercise))
            issues.push_back(
                {root.pathOf("exercise"), "must be \"exploration\", \"diagnosis\", \"polypectomy\" or \"myomectomy\""});
    }
    if (const json* s = root.member("scope", true)) {
        scene::ObjectReader scope(*s, root.pathOf("scope"), issues);
        scope.read("opticDeg", h.scope.opticDeg, true);
        scope.read("diameterMm", h.scope.diameterMm, true);
        scope.read("fieldOfViewDeg", h.scope.fieldOfViewDeg, true);
        scope.read("focusNearMm", h.scope.focusNearMm, true);
        scope.read("focusFarMm", h.scope.focusFarMm, true);
        scope.finish();
    }
    if (const json* f = root.member("fluid", true)) {
        scene::ObjectReader fluid(*f, root.pathOf("fluid"), issues);
        fluid.read("pumpPressureKpa", h.fluid.pumpPressureKpa, true);
        fluid.read("meanArterialPressureKpa", h.fluid.meanArterialPressureKpa, true);
        fluid.read("deficitWarningMl", h.fluid.deficitWarningMl, true);
        fluid.read("deficitLimitMl", h.fluid.deficitLimitMl, true);
        // Trials recorded before the medium was chosen ran on saline in a healthy patient.
        if (const json* m = fluid.member("medium")) {
            if (!m->is_string() || !fromString(m->get_ref<const std::string&>(), h.fluid.medium))
                issues.push_back({fluid.pathOf("medium"), "must be \"saline\" or \"glycine\""});
        }
        fluid.read("elderlyOrComorbid", h.fluid.elderlyOrComorbid);
        fluid.finish();
    }
    root.read("device", h.device, true);
    root.read("startedUtc", h.startedUtc);
}

} // namespace detail

std::string_view toString(Exercise exercise) {
    switch (exercise) {
    case Exercise::Exploration:
        return "exploration";
    case Exercise::Diagnosis:
        return "diagnosis";
    case Exercise::Polypectomy:
        return "polypectomy";
    case Exercise::Myomectomy:
        return "myomectomy";
    }
    return "exploration";
}

bool fromString(std::string_view key, Exercise& out) {
    if (key == "exploration")
        out = Exercise::Exploration;
    else if (key == "diagnosis")
        out = Exercise::Diagnosis;
    else if (key == "polypectomy")
        out = Exercise::Polypectomy;
    else if (key == "myomectomy")
        out = Exercise::Myomectomy;
    else
        return false;
    return true;
}

std::string_view toString(DistensionMedium medium) {
    return medium == DistensionMedium::Glycine ? "glycine" : "saline";
}

bool fromString(std::string_view key, DistensionMedium& out) {
    if (key == "saline")
        out = DistensionMedium::Saline;
    else if (key == "glycine")
        out = DistensionMedium::Glycine;
    else
        return false;
    return true;
}

FluidSettings withGuidelineDeficits(FluidSettings settings) {
    // Limits: AAGL 2013 and BSGE/ESGE 2016. Warnings: the AAGL's 1000 mL alert for an isotonic medium in a healthy
    // woman; elsewhere the guidelines give a limit only, and the warning comes at the next lower limit of the table
    // (750 mL) or, below it, 250 mL before the limit (this project's choice).
    const bool hypotonic = settings.medium == DistensionMedium::Glycine;
    if (!settings.elderlyOrComorbid) {
        settings.deficitLimitMl = hypotonic ? 1000.0 : 2500.0;
        settings.deficitWarningMl = hypotonic ? 750.0 : 1000.0;
    } else {
        settings.deficitLimitMl = hypotonic ? 750.0 : 1500.0;
        settings.deficitWarningMl = hypotonic ? 500.0 : 750.0;
    }
    return settings;
}

Status checkFluidSettings(const FluidSettings& f) {
    struct Field {
        const char* name;
        double value, lo, hi;
        const char* unit;
    };
    const Field fields[] = {
        {"pumpPressureKpa", f.pumpPressureKpa, 2.7, 20.0, " kPa (20-150 mmHg)"},
        {"meanArterialPressureKpa", f.meanArterialPressureKpa, 6.7, 20.0, " kPa (50-150 mmHg)"},
        {"deficitWarningMl", f.deficitWarningMl, 100.0, 5000.0, " mL"},
        {"deficitLimitMl", f.deficitLimitMl, 100.0, 5000.0, " mL"},
    };
    for (const Field& field : fields)
        if (!(std::isfinite(field.value) && field.value >= field.lo && field.value <= field.hi))
            return fail(ErrorCode::InvalidInput, std::string("fluid.") + field.name + ": " + numberText(field.value) +
                                                     " is outside " + numberText(field.lo) + "-" +
                                                     numberText(field.hi) + field.unit);
    if (!(f.deficitLimitMl > f.deficitWarningMl))
        return fail(ErrorCode::InvalidInput, "fluid.deficitLimitMl: " + numberText(f.deficitLimitMl) +
                                                 " must be above deficitWarningMl (" + numberText(f.deficitWarningMl) +
                                                 ")");
    return {};
}

Status writeTrial(const Trial& trial, const std::string& path) {
    HS_TRY(detail::checkHeader(trial.header, path));
    for (std::size_t i = 0; i < trial.samples.size(); ++i)
        HS_TRY(checkSample(trial.samples[i], i, path));
    const std::string header = headerJson(trial.header);
    return io::writeAtomically(path, [&](const std::string& tmpPath) -> Status {
        std::FILE* file = std::fopen(tmpPath.c_str(), "wb");
        if (!file)
            return fail(ErrorCode::IoError, tmpPath + ": cannot create: " + systemMessage(errno));
        return writeTo(file, trial, header, path);
    });
}

Result<Trial> readTrial(const std::string& path, const TrialReadLimits& limits) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        return fail(ErrorCode::NotFound, path + ": no such file");
    if (!std::filesystem::is_regular_file(status))
        return fail(ErrorCode::InvalidInput, path + ": is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec)
        return fail(ErrorCode::IoError, path + ": cannot get the file size: " + ec.message());
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file)
        return fail(ErrorCode::IoError, path + ": cannot open: " + systemMessage(errno));
    FileSource source(file, size);
    return parseFrom(source, path, limits);
}

Result<Trial> parseTrial(const std::string& bytes, const std::string& name, const TrialReadLimits& limits) {
    MemorySource source(bytes);
    return parseFrom(source, name, limits);
}

} // namespace hs::sim
