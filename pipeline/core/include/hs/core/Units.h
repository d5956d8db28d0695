#pragma once
/// Units used throughout hysteroscene. Every quantity is stored in these units; names or comments say which.
///
///   length    millimetre (mm)           positions, sizes, edge lengths
///   time      second (s)                durations, time steps
///   stress    kilopascal (kPa)          Young's modulus, pressure
///   density   kilogram per cubic metre  (kg/m^3)
///   volume    cubic millimetre (mm^3) inside the pipeline; millilitre (mL = 1000 mm^3) in clinical reports
///   angle     degree in files and user parameters; radian inside computations
///   force     newton (N) in the simulator

namespace hs::units {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMm3PerMl = 1000.0;           ///< 1 mL = 1 cm^3 = 1000 mm^3
constexpr double kKpaPerMmHg = 0.133322387415; ///< 1 mmHg in kPa
constexpr double kMmPerCm = 10.0;

constexpr double degToRad(double deg) {
    return deg * kPi / 180.0;
}
constexpr double radToDeg(double rad) {
    return rad * 180.0 / kPi;
}
constexpr double mlFromMm3(double mm3) {
    return mm3 / kMm3PerMl;
}
constexpr double mm3FromMl(double ml) {
    return ml * kMm3PerMl;
}
constexpr double kpaFromMmHg(double mmHg) {
    return mmHg * kKpaPerMmHg;
}

} // namespace hs::units
