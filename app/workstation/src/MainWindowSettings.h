#pragma once
/// The settings keys the main window's parts share (private to the workstation library).

namespace hs::workstation {

inline constexpr const char* kGeometryKey = "window/geometry";
inline constexpr const char* kStateKey = "window/state";
inline constexpr const char* kRecentFilesKey = "files/recent";
inline constexpr const char* kLastFolderKey = "files/lastFolder";

} // namespace hs::workstation
