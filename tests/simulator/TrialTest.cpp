// Trial files: written and read back bit for bit; malformed files refused with the file and the field named.
#include "hs/sim/Trial.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace hs::sim {
namespace {

Trial sampleTrial(std::size_t count, std::uint64_t seed = 7) {
    Trial trial;
    trial.header.sceneSha256 = std::string(64, 'a');
    trial.header.seed = 0xFFFFFFFFFFFFFFF1ull; // above 2^63: the JSON must keep every bit
    trial.header.physics.engine = "test-engine/3";
    trial.header.physics.stepS = 0.002;
    trial.header.physics.solverIterations = 7;
    trial.header.exercise = Exercise::Diagnosis;
    trial.header.scope.opticDeg = 12.0;
    trial.header.scope.diameterMm = 4.0;
    trial.header.fluid.pumpPressureKpa = 0.1 + 10.0;
    trial.header.fluid.medium = DistensionMedium::Glycine;
    trial.header.fluid.elderlyOrComorbid = true;
    trial.header.device = "scripted:push \"wall\".json";
    trial.header.startedUtc = "2024-05-01T10:00:00Z";
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < count; ++i) {
        DeviceSample s;
        s.tick = i;
        s.insertionMm = kMinInsertionMm + unit(rng) * (kMaxInsertionMm - kMinInsertionMm);
        s.pitchDeg = (unit(rng) * 2.0 - 1.0) * kMaxPivotDeg;
        s.yawDeg = (unit(rng) * 2.0 - 1.0) * kMaxPivotDeg;
        s.rollDeg = (unit(rng) * 2.0 - 1.0) * kMaxRollDeg;
        s.cameraRollDeg = i == 3 ? -0.0 : 5e-320; // signed zero and a subnormal survive too
        s.inflow = unit(rng);
        s.outflow = unit(rng);
        s.buttons = static_cast<std::uint32_t>(i % 16);
        s.workingElementMm = unit(rng) * kMaxWorkingElementMm;
        s.instrument = static_cast<std::uint32_t>(i % 2);
        trial.samples.push_back(s);
    }
    return trial;
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

/// `bytes` of a trial file with its header replaced by `header`.
std::string withHeader(const std::string& bytes, const std::string& header) {
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i)
        length |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
    std::string out = bytes.substr(0, 8);
    const auto size = static_cast<std::uint32_t>(header.size());
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((size >> (8 * i)) & 0xFFu));
    return out + header + bytes.substr(12 + length);
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Where the sample records start in the bytes of a trial file.
std::size_t samplesOffset(const std::string& bytes) {
    std::uint32_t headerLength = 0;
    for (int i = 0; i < 4; ++i)
        headerLength |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
    return 12 + headerLength + 8;
}

void putDouble(std::string& bytes, std::size_t at, double v) {
    std::memcpy(&bytes[at], &v, sizeof v); // the test runs on little-endian hosts, like the file
}

::testing::AssertionResult refusedNaming(const Result<Trial>& result, const std::string& name,
                                         const std::string& field) {
    if (result.ok())
        return ::testing::AssertionFailure() << "accepted";
    const std::string& detail = result.error().detail;
    if (detail.find(name) == std::string::npos || detail.find(field) == std::string::npos)
        return ::testing::AssertionFailure() << "message does not name " << name << " and " << field << ": " << detail;
    return ::testing::AssertionSuccess();
}

class TrialFile : public ::testing::Test {
protected:
    void SetUp() override {
        path = dir.file("session.hstrial");
        ASSERT_TRUE(writeTrial(sampleTrial(50), path).ok());
        bytes = fileBytes(path);
    }
    test::TempDir dir{"hs-trial"};
    std::string path;
    std::string bytes;
};

TEST_F(TrialFile, ReadsBackBitForBit) {
    const Trial original = sampleTrial(50);
    auto read = readTrial(path);
    ASSERT_TRUE(read.ok()) << read.error().detail;
    EXPECT_EQ(read->header.sceneSha256, original.header.sceneSha256);
    EXPECT_EQ(read->header.seed, original.header.seed);
    EXPECT_EQ(read->header.exercise, Exercise::Diagnosis);
    EXPECT_TRUE(sameBits(read->header.fluid.pumpPressureKpa, original.header.fluid.pumpPressureKpa));
    EXPECT_EQ(read->header.scope.diameterMm, 4.0);
    EXPECT_EQ(read->header.fluid.medium, DistensionMedium::Glycine);
    EXPECT_TRUE(read->header.fluid.elderlyOrComorbid);
    EXPECT_EQ(read->header.device, original.header.device);
    EXPECT_EQ(read->header.startedUtc, original.header.startedUtc);
    EXPECT_EQ(read->header.physics.engine, "test-engine/3");
    EXPECT_EQ(read->header.physics.stepS, 0.002);
    EXPECT_EQ(read->header.physics.solverIterations, 7);
    ASSERT_EQ(read->samples.size(), original.samples.size());
    for (std::size_t i = 0; i < original.samples.size(); ++i) {
        const DeviceSample& a = original.samples[i];
        const DeviceSample& b = read->samples[i];
        EXPECT_EQ(a.tick, b.tick);
        EXPECT_TRUE(sameBits(a.insertionMm, b.insertionMm) && sameBits(a.pitchDeg, b.pitchDeg) &&
                    sameBits(a.yawDeg, b.yawDeg) && sameBits(a.rollDeg, b.rollDeg) &&
                    sameBits(a.cameraRollDeg, b.cameraRollDeg) && sameBits(a.inflow, b.inflow) &&
                    sameBits(a.outflow, b.outflow) && sameBits(a.workingElementMm, b.workingElementMm))
            << "sample " << i;
        EXPECT_EQ(a.buttons, b.buttons);
        EXPECT_EQ(a.instrument, b.instrument);
    }
    // Writing what was read gives the same bytes.
    const std::string again = dir.file("again.hstrial");
    ASSERT_TRUE(writeTrial(*read, again).ok());
    EXPECT_EQ(fileBytes(again), bytes);
}

TEST_F(TrialFile, HasTheDocumentedLayout) {
    EXPECT_EQ(bytes.substr(0, 8), "HSTRIAL2");
    const std::size_t records = samplesOffset(bytes);
    EXPECT_EQ(bytes.size(), records + 50 * 80);
    std::uint64_t tick = 0;
    std::memcpy(&tick, &bytes[records + 80], 8);
    EXPECT_EQ(tick, 1u);
    std::uint32_t instrument = 0;
    std::memcpy(&instrument, &bytes[records + 80 + 76], 4);
    EXPECT_EQ(instrument, 1u);
}

TEST_F(TrialFile, ReadsAnOlderTrialAsTheDiagnosticScopes) {
    // An HSTRIAL1 file (72-byte samples: no working element, buttons, a zero word) made from the same samples.
    Trial trial = sampleTrial(20);
    for (DeviceSample& s : trial.samples) {
        s.buttons &= kButtonMark | kButtonCapture;
        s.workingElementMm = 0.0;
        s.instrument = kInstrumentNone;
    }
    const std::string v2 = dir.file("v2.hstrial");
    ASSERT_TRUE(writeTrial(trial, v2).ok());
    const std::string written = fileBytes(v2);
    const std::size_t records = samplesOffset(written);
    std::string v1 = written.substr(0, records);
    v1[7] = '1';
    for (std::size_t i = 0; i < trial.samples.size(); ++i) {
        v1 += written.substr(records + 80 * i, 64);     // tick and the seven doubles
        v1 += written.substr(records + 80 * i + 72, 4); // buttons
        v1 += std::string(4, '\0');
    }
    auto read = parseTrial(v1, "old.hstrial");
    ASSERT_TRUE(read.ok()) << read.error().detail;
    ASSERT_EQ(read->samples.size(), trial.samples.size());
    for (std::size_t i = 0; i < trial.samples.size(); ++i) {
        EXPECT_TRUE(sameBits(read->samples[i].insertionMm, trial.samples[i].insertionMm));
        EXPECT_EQ(read->samples[i].buttons, trial.samples[i].buttons);
        EXPECT_EQ(read->samples[i].workingElementMm, 0.0);
        EXPECT_EQ(read->samples[i].instrument, kInstrumentNone);
    }
    // Its reserved word must stay zero.
    std::string reserved = v1;
    reserved[records + 72 + 68] = 1;
    EXPECT_TRUE(refusedNaming(parseTrial(reserved, "old.hstrial"), "old.hstrial", "samples[1].reserved"));
}

TEST_F(TrialFile, RefusesATruncatedFile) {
    EXPECT_TRUE(
        refusedNaming(parseTrial(bytes.substr(0, bytes.size() - 1), "cut.hstrial"), "cut.hstrial", "sampleCount"));
    EXPECT_TRUE(refusedNaming(parseTrial(bytes.substr(0, 20), "cut.hstrial"), "cut.hstrial", "header"));
    EXPECT_TRUE(refusedNaming(parseTrial(bytes.substr(0, 5), "cut.hstrial"), "cut.hstrial", "magic"));
    EXPECT_TRUE(refusedNaming(parseTrial(bytes + "x", "long.hstrial"), "long.hstrial", "sampleCount"));
}

TEST_F(TrialFile, RefusesAWrongMagic) {
    std::string wrong = bytes;
    wrong[7] = '3';
    EXPECT_TRUE(refusedNaming(parseTrial(wrong, "v3.hstrial"), "v3.hstrial", "magic"));
}

TEST_F(TrialFile, RefusesHugeCountsBeforeAllocating) {
    const std::size_t countAt = samplesOffset(bytes) - 8;
    std::string huge = bytes;
    const std::uint64_t count = 1ull << 60;
    std::memcpy(&huge[countAt], &count, 8);
    auto result = parseTrial(huge, "huge.hstrial");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::LimitExceeded);
    EXPECT_TRUE(refusedNaming(result, "huge.hstrial", "sampleCount"));
    // Within the limit but more than the file holds: refused by the file's size.
    const std::uint64_t many = TrialReadLimits{}.maxSamples;
    std::memcpy(&huge[countAt], &many, 8);
    EXPECT_TRUE(refusedNaming(parseTrial(huge, "many.hstrial"), "many.hstrial", "sampleCount"));
    // A header length above the limit.
    std::string longHeader = bytes;
    const std::uint32_t length = 0xFFFFFFF0u;
    std::memcpy(&longHeader[8], &length, 4);
    EXPECT_TRUE(refusedNaming(parseTrial(longHeader, "h.hstrial"), "h.hstrial", "headerLength"));
}

TEST_F(TrialFile, RefusesNaNAndOutOfRangeSamples) {
    const std::size_t records = samplesOffset(bytes);
    std::string nan = bytes;
    putDouble(nan, records + 3 * 80 + 8, std::nan(""));
    EXPECT_TRUE(refusedNaming(parseTrial(nan, "nan.hstrial"), "nan.hstrial", "samples[3].insertionMm"));
    std::string pitch = bytes;
    putDouble(pitch, records + 10 * 80 + 16, 61.0);
    EXPECT_TRUE(refusedNaming(parseTrial(pitch, "p.hstrial"), "p.hstrial", "samples[10].pitchDeg"));
    std::string valve = bytes;
    putDouble(valve, records + 10 * 80 + 56, 1.5);
    EXPECT_TRUE(refusedNaming(parseTrial(valve, "v.hstrial"), "v.hstrial", "samples[10].outflow"));
    std::string buttons = bytes;
    buttons[records + 80 + 72] = 64; // the first bit no button has
    EXPECT_TRUE(refusedNaming(parseTrial(buttons, "b.hstrial"), "b.hstrial", "samples[1].buttons"));
    std::string loop = bytes;
    putDouble(loop, records + 10 * 80 + 64, kMaxWorkingElementMm + 1.0);
    EXPECT_TRUE(refusedNaming(parseTrial(loop, "w.hstrial"), "w.hstrial", "samples[10].workingElementMm"));
    std::string instrument = bytes;
    instrument[records + 80 + 76] = 9;
    EXPECT_TRUE(refusedNaming(parseTrial(instrument, "i.hstrial"), "i.hstrial", "samples[1].instrument"));
}

TEST_F(TrialFile, RefusesTicksThatAreNotConsecutive) {
    std::string gap = bytes;
    const std::uint64_t tick = 7;
    std::memcpy(&gap[samplesOffset(bytes) + 5 * 80], &tick, 8);
    EXPECT_TRUE(refusedNaming(parseTrial(gap, "gap.hstrial"), "gap.hstrial", "samples[5].tick"));

    Trial trial = sampleTrial(10);
    trial.samples[4].tick = 3;
    const std::string out = dir.file("bad.hstrial");
    const Status written = writeTrial(trial, out);
    ASSERT_FALSE(written.ok());
    EXPECT_NE(written.error().detail.find("samples[4].tick"), std::string::npos) << written.error().detail;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(TrialFile, RefusesHeaderFieldsOutOfRange) {
    Trial trial = sampleTrial(2);
    trial.header.fluid.pumpPressureKpa = 30.0;
    auto status = writeTrial(trial, dir.file("f.hstrial"));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("header.fluid.pumpPressureKpa"), std::string::npos);
    EXPECT_NE(status.error().detail.find("2.7-20"), std::string::npos) << status.error().detail;

    // The same in a file: the header's JSON edited in place (same length, so the layout holds).
    std::string edited = bytes;
    const std::size_t at = edited.find("\"diameterMm\":4.0");
    ASSERT_NE(at, std::string::npos);
    edited.replace(at, 16, "\"diameterMm\":7.0");
    EXPECT_TRUE(refusedNaming(parseTrial(edited, "d.hstrial"), "d.hstrial", "diameterMm"));
    std::string exercise = bytes;
    const std::size_t e = exercise.find("diagnosis");
    exercise.replace(e, 9, "diagnoses");
    EXPECT_TRUE(refusedNaming(parseTrial(exercise, "e.hstrial"), "e.hstrial", "exercise"));
}

TEST_F(TrialFile, RefusesAHeaderWithoutItsPhysicsOrFromAnOlderFormat) {
    Trial trial = sampleTrial(10);
    trial.header.physics.engine.clear();
    Status status = writeTrial(trial, dir.file("no-engine.hstrial"));
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().detail.find("header.physics.engine"), std::string::npos) << status.error().detail;
    trial = sampleTrial(10);
    trial.header.physics.solverIterations = 0;
    status = writeTrial(trial, dir.file("iterations.hstrial"));
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().detail.find("header.physics.solverIterations"), std::string::npos);
    // A version 1 header (before the physics was recorded) is refused by its version.
    trial = sampleTrial(10);
    const std::string old = dir.file("old.hstrial");
    ASSERT_TRUE(writeTrial(trial, old));
    std::string oldBytes = fileBytes(old);
    const std::size_t at = oldBytes.find("\"version\":2");
    ASSERT_NE(at, std::string::npos);
    oldBytes[at + 10] = '1';
    EXPECT_TRUE(refusedNaming(parseTrial(oldBytes, "old.hstrial"), "old.hstrial", "/version"));
}

TEST(Trial, ReadingAMissingFileNamesIt) {
    auto result = readTrial("/nonexistent/x.hstrial");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, ErrorCode::NotFound);
    EXPECT_NE(result.error().detail.find("/nonexistent/x.hstrial"), std::string::npos);
}

TEST_F(TrialFile, AHeaderWithoutTheMediumIsSalineInAHealthyPatientAndAnUnknownMediumIsRefusedByName) {
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i)
        length |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
    std::string header = bytes.substr(12, length);
    const std::string fields = ",\"medium\":\"glycine\",\"elderlyOrComorbid\":true";
    const std::size_t at = header.find(fields);
    ASSERT_NE(at, std::string::npos) << header;
    std::string older = header;
    older.erase(at, fields.size());
    const std::string olderPath = dir.file("older.hstrial");
    std::ofstream(olderPath, std::ios::binary) << withHeader(bytes, older);
    auto read = readTrial(olderPath);
    ASSERT_TRUE(read.ok()) << read.error().detail;
    EXPECT_EQ(read->header.fluid.medium, DistensionMedium::Saline);
    EXPECT_FALSE(read->header.fluid.elderlyOrComorbid);

    std::string unknown = header;
    unknown.replace(unknown.find("\"glycine\""), 9, "\"sorbitol\"");
    const std::string unknownPath = dir.file("unknown.hstrial");
    std::ofstream(unknownPath, std::ios::binary) << withHeader(bytes, unknown);
    EXPECT_TRUE(refusedNaming(readTrial(unknownPath), unknownPath, "fluid/medium"));
}

TEST(FluidSettings, TheGuidelinesDeficitsFollowTheMediumAndThePatient) {
    // AAGL 2013 and BSGE/ESGE 2016: stop at 2500 / 1000 mL (isotonic / hypotonic), 1500 / 750 mL in elderly or
    // comorbid patients; each warning below its limit.
    const struct {
        DistensionMedium medium;
        bool elderly;
        double warning, limit;
    } rows[] = {{DistensionMedium::Saline, false, 1000.0, 2500.0},
                {DistensionMedium::Saline, true, 750.0, 1500.0},
                {DistensionMedium::Glycine, false, 750.0, 1000.0},
                {DistensionMedium::Glycine, true, 500.0, 750.0}};
    for (const auto& row : rows) {
        FluidSettings f;
        f.medium = row.medium;
        f.elderlyOrComorbid = row.elderly;
        f = withGuidelineDeficits(f);
        EXPECT_EQ(f.deficitLimitMl, row.limit) << toString(row.medium) << " " << row.elderly;
        EXPECT_EQ(f.deficitWarningMl, row.warning) << toString(row.medium) << " " << row.elderly;
        EXPECT_TRUE(checkFluidSettings(f).ok());
    }
    // The defaults are the healthy patient's with saline.
    const FluidSettings defaults;
    const FluidSettings saline = withGuidelineDeficits(defaults);
    EXPECT_EQ(defaults.deficitLimitMl, saline.deficitLimitMl);
    EXPECT_EQ(defaults.deficitWarningMl, saline.deficitWarningMl);
    DistensionMedium back = DistensionMedium::Saline;
    EXPECT_TRUE(fromString("glycine", back));
    EXPECT_EQ(back, DistensionMedium::Glycine);
    EXPECT_FALSE(fromString("sorbitol", back));
}

TEST(FluidSettings, RangesAreChecked) {
    EXPECT_TRUE(checkFluidSettings({}).ok());
    FluidSettings f;
    f.deficitWarningMl = 3000.0;
    f.deficitLimitMl = 2000.0;
    auto status = checkFluidSettings(f);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("deficitLimitMl"), std::string::npos);
    f = {};
    f.meanArterialPressureKpa = std::nan("");
    EXPECT_FALSE(checkFluidSettings(f).ok());
}

TEST(Exercise, NamesReadBack) {
    for (Exercise e : {Exercise::Exploration, Exercise::Diagnosis}) {
        Exercise back = Exercise::Exploration;
        ASSERT_TRUE(fromString(toString(e), back));
        EXPECT_EQ(back, e);
    }
    Exercise unchanged = Exercise::Diagnosis;
    EXPECT_FALSE(fromString("Exploration", unchanged));
    EXPECT_EQ(unchanged, Exercise::Diagnosis);
}

} // namespace
} // namespace hs::sim
