// The scene package reader on a folder. The input is a folder image (tests/fuzz/pack-folder.py writes one):
// entries of a type byte ('f' file, 'd' folder, 'l' symbolic link), a name length byte, the name, a 4-byte
// little-endian size and the content (a link's target). The harness unpacks it into a scratch folder and, so that
// the fuzzer reaches the file parsers behind the checksums, rewrites the manifest's sizes and SHA-256 sums to the
// files' real ones; then readScenePackage. Property: an error names the folder.

#include "FuzzSupport.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <sstream>

namespace {

namespace fs = std::filesystem;

/// Names the harness itself writes: relative, [A-Za-z0-9._-/], no "." or ".." part, at most 3 levels.
bool safeName(const std::string& name) {
    if (name.empty() || name.front() == '/' || name.back() == '/')
        return false;
    int depth = 0;
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t end = std::min(name.find('/', start), name.size());
        const std::string part = name.substr(start, end - start);
        if (part.empty() || part == "." || part == ".." || ++depth > 3)
            return false;
        start = end + 1;
    }
    for (const char c : name)
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
              c == '-' || c == '/'))
            return false;
    return true;
}

void unpack(const std::uint8_t* data, std::size_t size, const fs::path& root) {
    std::size_t at = 0;
    while (at + 2 <= size) {
        const char type = static_cast<char>(data[at]);
        const std::size_t nameLength = data[at + 1];
        at += 2;
        if (at + nameLength + 4 > size)
            return;
        const std::string name(reinterpret_cast<const char*>(data + at), nameLength);
        at += nameLength;
        const std::size_t length = static_cast<std::size_t>(data[at]) | static_cast<std::size_t>(data[at + 1]) << 8 |
                                   static_cast<std::size_t>(data[at + 2]) << 16 |
                                   static_cast<std::size_t>(data[at + 3]) << 24;
        at += 4;
        if (length > size - at || !safeName(name))
            return;
        const std::string content(reinterpret_cast<const char*>(data + at), length);
        at += length;
        std::error_code ec;
        const fs::path target = root / name;
        fs::create_directories(target.parent_path(), ec);
        if (type == 'd')
            fs::create_directories(target, ec);
        else if (type == 'l' && safeName(content))
            fs::create_symlink(content, target, ec);
        else if (type == 'f')
            std::ofstream(target, std::ios::binary).write(content.data(), static_cast<std::streamsize>(length));
    }
}

/// The manifest's "bytes" and "sha256" of every listed regular file set to the real ones.
void fixChecksums(const fs::path& root) {
    std::error_code status;
    // A folder named manifest.json opens, and libstdc++ then throws on the first read (EISDIR).
    if (!fs::is_regular_file(fs::symlink_status(root / "manifest.json", status)))
        return;
    std::ifstream in(root / "manifest.json", std::ios::binary);
    if (!in)
        return;
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    nlohmann::json manifest = nlohmann::json::parse(text, nullptr, false);
    if (!manifest.is_object() || !manifest.contains("files") || !manifest["files"].is_array())
        return;
    for (auto& entry : manifest["files"]) {
        if (!entry.is_object() || !entry.contains("path") || !entry["path"].is_string())
            continue;
        const std::string name = entry["path"].get<std::string>();
        std::error_code ec;
        if (!safeName(name) || !fs::is_regular_file(fs::symlink_status(root / name, ec)))
            continue;
        std::ifstream file(root / name, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        entry["bytes"] = bytes.size();
        entry["sha256"] = hs::scene::sha256Hex(bytes);
    }
    std::ofstream(root / "manifest.json", std::ios::binary | std::ios::trunc) << manifest.dump(1);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hs::fuzz::removeScratch("package");
    const fs::path root = hs::fuzz::scratchFolder() / "package";
    std::error_code ec;
    fs::create_directories(root, ec);
    unpack(data, size, root);
    fixChecksums(root);
    hs::scene::PackageReadLimits limits;
    limits.maxFileBytes = 16 << 20;
    limits.maxTotalBytes = 64 << 20;
    const auto scene = hs::scene::readScenePackage(root.string(), limits);
    if (!scene.ok())
        hs::fuzz::check(scene.error().detail.find(root.string()) != std::string::npos, "an error names the folder",
                        scene.error().detail);
    hs::fuzz::removeScratch("package");
    return 0;
}
