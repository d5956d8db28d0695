#pragma once
/// SHA-256 (FIPS 180-4) of byte strings and files, for the scene package's manifest. Self-contained so that the
/// checksums do not depend on which crypto library a platform ships; checked against the NIST test vectors.

#include "hs/core/Result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hs::scene {

class Sha256 {
public:
    Sha256();
    void update(const void* data, std::size_t size);
    void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
    /// The digest; the object must not be updated afterwards.
    std::array<std::uint8_t, 32> finish();

private:
    void block(const std::uint8_t* p);
    std::array<std::uint32_t, 8> m_h{};
    std::array<std::uint8_t, 64> m_buffer{};
    std::size_t m_buffered = 0;
    std::uint64_t m_length = 0; ///< bytes
};

/// Lower-case hex SHA-256 of `bytes`.
std::string sha256Hex(std::string_view bytes);

/// Lower-case hex SHA-256 and size of a file, read in chunks; reading stops with LimitExceeded past `maxBytes`.
struct FileDigest {
    std::string sha256;
    std::int64_t bytes = 0;
};
[[nodiscard]] Result<FileDigest> sha256File(const std::string& path, std::int64_t maxBytes);

} // namespace hs::scene
