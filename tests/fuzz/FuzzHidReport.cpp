// The HID protocol's codec (docs/haptics-protocol.md): reports from hardware that others build. The first byte picks
// what the rest is: an input report, an output report as a device reads it, the limits or calibration feature report,
// or a force command (seven doubles) encoded for the wire.
// Properties: a decoded input sample is inside Device.h's ranges; a decoded output never exceeds the limits; an
// encoded force command never exceeds the limits on the wire; accepted feature reports are within the protocol's
// bounds.

#include "FuzzSupport.h"
#include "hs/haptics/HidProtocol.h"
#include "hs/sim/Device.h"

#include <cmath>
#include <cstring>

namespace {

using namespace hs::haptics;
using namespace hs::haptics::hid;

bool within(double value, double limit) {
    return std::isfinite(value) && std::abs(value) <= limit * (1.0 + 1e-12);
}

void checkWithin(const ForceCommand& c, const DeviceLimits& limits) {
    hs::fuzz::check(within(c.insertionForceN, limits.maxForceN), "the force stays within the limit");
    hs::fuzz::check(within(c.pitchTorqueNmm, limits.maxTorqueNmm) && within(c.yawTorqueNmm, limits.maxTorqueNmm) &&
                        within(c.rollTorqueNmm, limits.maxTorqueNmm),
                    "the torques stay within the limit");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hs::haptics;
    using namespace hs::haptics::hid;
    if (size < 1)
        return 0;
    const std::uint8_t kind = data[0] % 5;
    const std::uint8_t* body = data + 1;
    const std::size_t bytes = size - 1;
    const DeviceLimits limits{5.0, 300.0};
    switch (kind) {
    case 0: {
        for (const std::uint8_t version : {kProtocolVersion1, kProtocolVersion2}) {
            const auto input = decodeInputReport(body, bytes, Calibration{}, version);
            if (input.ok())
                hs::fuzz::check(hs::sim::isValid(input->sample), "a decoded sample is inside its ranges");
        }
        break;
    }
    case 1: {
        const auto output = decodeOutputReport(body, bytes, limits);
        if (output.ok())
            checkWithin(output->command, limits);
        break;
    }
    case 2: {
        const auto declared = decodeLimitsReport(body, bytes);
        if (declared.ok())
            hs::fuzz::check(within(declared->maxForceN, kMaxDeclaredForceN) &&
                                within(declared->maxTorqueNmm, kMaxDeclaredTorqueNmm),
                            "declared limits stay within the protocol's");
        break;
    }
    case 3: {
        const auto calibration = decodeCalibrationReport(body, bytes);
        if (calibration.ok()) {
            hs::fuzz::check(checkCalibration(*calibration).ok(), "an accepted calibration passes its check");
            // Any input report decoded with it still gives samples inside their ranges.
            const auto input = decodeInputReport(body, std::min(bytes, kInputReportBytes), *calibration);
            if (input.ok())
                hs::fuzz::check(hs::sim::isValid(input->sample), "a calibrated sample is inside its ranges");
        }
        break;
    }
    default: {
        double values[5] = {0, 0, 0, 0, 0};
        std::memcpy(values, body, std::min(bytes, sizeof(values)));
        ForceCommand command;
        command.enabled = bytes > sizeof(values) ? (body[sizeof(values)] & 1) != 0 : true;
        command.insertionForceN = values[0];
        command.pitchTorqueNmm = values[1];
        command.yawTorqueNmm = values[2];
        command.rollTorqueNmm = values[3];
        const auto wire = encodeOutputReport(command, limits);
        const auto back = decodeOutputReport(wire.data(), wire.size(), limits);
        hs::fuzz::check(back.ok(), "an encoded output report decodes");
        if (back.ok())
            checkWithin(back->command, limits);
        break;
    }
    }
    return 0;
}
