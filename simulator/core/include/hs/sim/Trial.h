#pragma once
/// A trial: the device samples of one session at 1 kHz with what is needed to replay it (the scene's checksum, the
/// seed, the scope and the fluid settings). Replaying the samples through a World built from the same package and
/// settings gives the same metrics, bit for bit (docs/simulator.md, "Record and replay"; the file layout is in
/// docs/file-formats.md, "Trial files").
///
/// On disk (little-endian): the 8 bytes "HSTRIAL2", a uint32 header length, the header as UTF-8 JSON, a uint64
/// sample count, then that many 80-byte records: uint64 tick, eight float64 (insertionMm, pitchDeg, yawDeg, rollDeg,
/// cameraRollDeg, inflow, outflow, workingElementMm), uint32 buttons, uint32 instrument. "HSTRIAL1" files (72-byte
/// records without the working element, uint32 buttons, uint32 zero) are read as the diagnostic scope's.

#include "hs/core/Result.h"
#include "hs/sim/Device.h"
#include "hs/sim/Scope.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::sim {

/// Which exercise a trial runs (docs/simulator.md, "Exercises").
enum class Exercise {
    Exploration, ///< "exploration": see the fundus, both tubal ostia and every wall
    Diagnosis,   ///< "diagnosis": mark each pathology seen
    Polypectomy, ///< "polypectomy": resect the polyps with the loop
    Myomectomy,  ///< "myomectomy": resect the submucous (FIGO 0-2) myomas with the loop
};
/// Whether the exercise cuts (the resectoscope's loop is live).
inline bool isOperative(Exercise exercise) {
    return exercise == Exercise::Polypectomy || exercise == Exercise::Myomectomy;
}
std::string_view toString(Exercise exercise);
bool fromString(std::string_view key, Exercise& out);

/// The distension medium (docs/simulator.md, "Fluid management"): an electrolyte for bipolar electrosurgery and
/// mechanical instruments, an electrolyte-free hypotonic one for monopolar electrosurgery.
enum class DistensionMedium {
    Saline,  ///< "saline": isotonic 0.9 % sodium chloride
    Glycine, ///< "glycine": hypotonic 1.5 % glycine
};
std::string_view toString(DistensionMedium medium);
bool fromString(std::string_view key, DistensionMedium& out);

/// Distension settings (docs/simulator.md, "Distension" and "Fluid management", with sources).
struct FluidSettings {
    double pumpPressureKpa = 10.7;         ///< kPa, the pump's set pressure (80 mmHg); 2.7-20 kPa (20-150 mmHg)
    double meanArterialPressureKpa = 11.3; ///< kPa, the patient's mean arterial pressure (85 mmHg); 6.7-20 kPa
    double deficitWarningMl = 1000.0;      ///< mL, the deficit that raises a warning; 100-5000
    double deficitLimitMl = 2500.0;        ///< mL, the deficit at which the procedure must stop; 100-5000, > warning
    DistensionMedium medium = DistensionMedium::Saline;
    bool elderlyOrComorbid = false; ///< the patient: the guidelines' lower deficit limits apply
};
/// `settings` with the deficit's warning and limit of the guidelines for its medium and patient (AAGL 2013,
/// BSGE/ESGE 2016: stop at 2500 mL of an isotonic medium, 1000 mL of a hypotonic one, 1500 / 750 mL in elderly or
/// comorbid patients; the warnings: docs/simulator.md, "Fluid management").
FluidSettings withGuidelineDeficits(FluidSettings settings);
/// InvalidInput naming the field and its range.
[[nodiscard]] Status checkFluidSettings(const FluidSettings& settings);

/// The physics that recorded a trial: a replay on another engine or with other settings would diverge silently,
/// so both are recorded and a replay must match them (checkReplay).
struct TrialPhysics {
    std::string engine;       ///< the physics engine and its version (physicsEngine() of the recording build)
    double stepS = 0.005;     ///< s, the physics step
    int solverIterations = 2; ///< the tissue solver's iterations (or substeps) per step
};

struct TrialHeader {
    std::string sceneSha256; ///< SHA-256 of the package's manifest.json, lower-case hex
    std::uint64_t seed = 1;  ///< the world's seed
    TrialPhysics physics;
    Exercise exercise = Exercise::Exploration;
    ScopeConfig scope;
    FluidSettings fluid;
    std::string device;     ///< where the samples came from ("keyboard", "hid:046d:c62b", "scripted:FILE")
    std::string startedUtc; ///< ISO 8601, informative only (not read by replay)
};

struct Trial {
    TrialHeader header;
    std::vector<DeviceSample> samples; ///< tick 0, 1, 2, ... without gaps
};

/// Limits for reading untrusted trial files.
struct TrialReadLimits {
    std::uint32_t maxHeaderBytes = 64 * 1024;
    std::uint64_t maxSamples = 4ull * 3600 * kDeviceRateHz; ///< four hours
};

/// Writes atomically (temporary file, then rename). InvalidInput for samples out of range or not consecutive ticks;
/// IoError naming the file.
[[nodiscard]] Status writeTrial(const Trial& trial, const std::string& path);
/// Reads and checks a trial file: magic, header fields and their ranges, sample count against the file's size,
/// every sample valid and consecutive. Errors name the file and the field.
[[nodiscard]] Result<Trial> readTrial(const std::string& path, const TrialReadLimits& limits = {});
/// The same from bytes in memory (`name` is used in messages).
[[nodiscard]] Result<Trial> parseTrial(const std::string& bytes, const std::string& name,
                                       const TrialReadLimits& limits = {});

} // namespace hs::sim
