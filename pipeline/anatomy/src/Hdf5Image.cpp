// A read-only HDF5 file driver over bytes in memory (see Hdf5Image.h for why the project has its own).
#include "Hdf5Image.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

namespace hs::anatomy::detail {

namespace {

/// What the property list carries: where the image is. HDF5 copies it with the list (fapl_copy / fapl_free).
struct ImageInfo {
    const std::uint8_t* bytes;
    std::size_t size;
};

/// An open file: HDF5's part first (the driver hands HDF5 a pointer to it), then ours.
struct ImageFile {
    H5FD_t pub;
    ImageInfo image;
    haddr_t eoa;
};
static_assert(offsetof(ImageFile, pub) == 0, "HDF5 casts between H5FD_t* and the driver's file");

ImageFile* imageFile(H5FD_t* file) {
    return reinterpret_cast<ImageFile*>(file);
}
const ImageFile* imageFile(const H5FD_t* file) {
    return reinterpret_cast<const ImageFile*>(file);
}

void* copyInfo(const void* info) {
    auto* copy = static_cast<ImageInfo*>(std::malloc(sizeof(ImageInfo)));
    if (copy)
        std::memcpy(copy, info, sizeof(ImageInfo));
    return copy;
}

herr_t freeInfo(void* info) {
    std::free(info);
    return 0;
}

H5FD_t* openImage(const char* /*name*/, unsigned flags, hid_t fapl, haddr_t /*maxaddr*/) {
    if (flags & (H5F_ACC_RDWR | H5F_ACC_TRUNC | H5F_ACC_CREAT))
        return nullptr; // read-only: an image is never written
    const auto* info = static_cast<const ImageInfo*>(H5Pget_driver_info(fapl));
    if (!info || !info->bytes || info->size == 0)
        return nullptr;
    auto* file = new (std::nothrow) ImageFile{};
    if (!file)
        return nullptr;
    file->image = *info;
    file->eoa = 0;
    return &file->pub;
}

herr_t closeImage(H5FD_t* file) {
    delete imageFile(file);
    return 0;
}

int compareImages(const H5FD_t* a, const H5FD_t* b) {
    const auto pa = reinterpret_cast<std::uintptr_t>(imageFile(a)->image.bytes);
    const auto pb = reinterpret_cast<std::uintptr_t>(imageFile(b)->image.bytes);
    return pa < pb ? -1 : pa > pb ? 1 : 0;
}

/// No feature: no metadata accumulation, no aggregation, no sieve buffer. Every read goes to `readImage`.
herr_t queryImage(const H5FD_t* /*file*/, unsigned long* flags) {
    if (flags)
        *flags = 0;
    return 0;
}

haddr_t imageEoa(const H5FD_t* file, H5FD_mem_t /*type*/) {
    return imageFile(file)->eoa;
}

herr_t setImageEoa(H5FD_t* file, H5FD_mem_t /*type*/, haddr_t addr) {
    imageFile(file)->eoa = addr;
    return 0;
}

haddr_t imageEof(const H5FD_t* file, H5FD_mem_t /*type*/) {
    return static_cast<haddr_t>(imageFile(file)->image.size);
}

/// Reads `size` bytes at `addr`. Like HDF5's own drivers, bytes past the end of the image read as zeros (HDF5 reads
/// ahead, up to its end of address space, when it guesses a header's size); a range whose end overflows fails.
herr_t readImage(H5FD_t* file, H5FD_mem_t /*type*/, hid_t /*dxpl*/, haddr_t addr, size_t size, void* buffer) {
    const ImageInfo& image = imageFile(file)->image;
    if (!buffer || addr == HADDR_UNDEF || size > HADDR_MAX - addr)
        return -1;
    auto* out = static_cast<std::uint8_t*>(buffer);
    std::size_t copied = 0;
    if (addr < image.size) {
        copied =
            static_cast<std::size_t>(image.size - addr) < size ? static_cast<std::size_t>(image.size - addr) : size;
        std::memcpy(out, image.bytes + addr, copied);
    }
    std::memset(out + copied, 0, size - copied);
    return 0;
}

herr_t writeImage(H5FD_t*, H5FD_mem_t, hid_t, haddr_t, size_t, const void*) {
    return -1;
}

H5FD_class_t imageClass() {
    H5FD_class_t c{};
    c.name = "hysteroscene-image";
    c.maxaddr = static_cast<haddr_t>(~std::size_t{0} - 1);
    c.fc_degree = H5F_CLOSE_WEAK;
    c.fapl_size = sizeof(ImageInfo);
    c.fapl_copy = copyInfo;
    c.fapl_free = freeInfo;
    c.open = openImage;
    c.close = closeImage;
    c.cmp = compareImages;
    c.query = queryImage;
    c.get_eoa = imageEoa;
    c.set_eoa = setImageEoa;
    c.get_eof = imageEof;
    c.read = readImage;
    c.write = writeImage;
    for (auto& type : c.fl_map)
        type = H5FD_MEM_DEFAULT;
    return c;
}

hid_t imageDriver() {
    static const H5FD_class_t cls = imageClass();
    static const hid_t id = H5FDregister(&cls);
    return id;
}

/// `width` bytes (2, 4 or 8) at `at` as an unsigned little-endian number; bytes past the image read as zero, as the
/// driver reads them.
std::uint64_t decode(const ImageInfo& image, std::uint64_t at, int width) {
    std::uint64_t value = 0;
    for (int i = width - 1; i >= 0; --i) {
        const std::uint64_t byte = at + static_cast<std::uint64_t>(i);
        value = (value << 8) | (byte >= at && byte < image.size ? image.bytes[byte] : 0u);
    }
    return value;
}

constexpr std::uint8_t kSuperblockSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
constexpr std::uint64_t kFreeListEnd = 1; ///< HDF5's H5HL_FREE_NULL

} // namespace

std::string findHdf5ImageDamage(const void* bytes, std::size_t size) {
    const ImageInfo image{static_cast<const std::uint8_t*>(bytes), size};
    if (!bytes || size == 0)
        return {};
    // The superblock, where HDF5 looks for it: at 0, 512, 1024, 2048, ... Its place is the base of every address.
    std::uint64_t base = 0;
    bool found = false;
    for (std::uint64_t at = 0; at + sizeof kSuperblockSignature <= size; at = at ? at * 2 : 512)
        if (std::memcmp(image.bytes + at, kSuperblockSignature, sizeof kSuperblockSignature) == 0) {
            base = at;
            found = true;
            break;
        }
    if (!found || base + 16 > size)
        return {}; // HDF5 refuses it by itself
    const std::uint8_t version = image.bytes[base + 8];
    const int addressBytes = version < 2 ? image.bytes[base + 13] : image.bytes[base + 9];
    const int lengthBytes = version < 2 ? image.bytes[base + 14] : image.bytes[base + 10];
    const auto supported = [](int n) { return n == 2 || n == 4 || n == 8; };
    if (!supported(addressBytes) || !supported(lengthBytes))
        return "the superblock gives " + std::to_string(addressBytes) + "-byte addresses and " +
               std::to_string(lengthBytes) + "-byte lengths (2, 4 or 8 bytes are read)";

    // Versions 0 and 1 may point to a driver information block. HDF5 reads the block's size from its header and
    // allocates that much before reading it: 2.75 GB from a 50-byte file, zero-filled past the image's end. The
    // block must lie inside the file. Its address follows the fixed part (24 bytes, 28 in version 1) and the base,
    // free-space and end-of-file addresses; all ones is "none".
    if (version < 2) {
        const std::uint64_t fixed = version == 0 ? 24 : 28;
        const std::uint64_t driver =
            decode(image, base + fixed + 3 * static_cast<std::uint64_t>(addressBytes), addressBytes);
        const std::uint64_t none = addressBytes == 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * addressBytes)) - 1;
        if (driver != none) {
            const std::uint64_t at = driver < size ? driver + base : size; // HDF5 adds the base to every address
            const std::uint64_t infoBytes = at < size ? decode(image, at + 4, 4) : 0;
            constexpr std::uint64_t kHeaderBytes = 16; // version, 3 reserved, info size (4), driver id (8)
            if (at >= size || kHeaderBytes + infoBytes > size - at)
                return "the driver information block at address " + std::to_string(driver) + " (" +
                       std::to_string(kHeaderBytes + infoBytes) + " bytes) does not fit in the file (" +
                       std::to_string(size) + " bytes)";
        }
    }

    // Every local heap prefix: "HEAP", version 0, 3 reserved bytes, data size, free list head, data address.
    const std::uint8_t heapSignature[4] = {'H', 'E', 'A', 'P'};
    const std::uint8_t* end = image.bytes + size;
    std::uint64_t steps = 0; // over all heaps' free lists
    for (const std::uint8_t* p = image.bytes; (p = std::search(p, end, heapSignature, heapSignature + 4)) != end; ++p) {
        const auto at = static_cast<std::uint64_t>(p - image.bytes);
        if (at + 8 > size || p[4] != 0)
            continue; // HDF5 refuses another version
        const std::uint64_t dataSize = decode(image, at + 8, lengthBytes);
        std::uint64_t block = decode(image, at + 8 + static_cast<std::uint64_t>(lengthBytes), lengthBytes);
        const std::uint64_t data =
            decode(image, at + 8 + 2 * static_cast<std::uint64_t>(lengthBytes), addressBytes) + base;
        // As H5HL__fl_deserialize: stop (HDF5 stops with an error) at an offset outside the data, a next offset of 0
        // or a block past the data's end. HDF5 writes free blocks apart, each at least two lengths long, so the
        // lists of all heaps together have fewer steps than the image has bytes; more means one came back on itself.
        while (block != kFreeListEnd && block < dataSize) {
            if (++steps > size)
                return "the local heap at byte " + std::to_string(at) + " has a free list that comes back on itself";
            const std::uint64_t next = decode(image, data + block, lengthBytes);
            const std::uint64_t length =
                decode(image, data + block + static_cast<std::uint64_t>(lengthBytes), lengthBytes);
            if (next == 0 || length > dataSize - block)
                break;
            block = next;
        }
    }
    return {};
}

hid_t hdf5ImageAccess(const void* bytes, std::size_t size) {
    const hid_t driver = imageDriver();
    if (driver < 0 || !bytes || size == 0)
        return -1;
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0)
        return -1;
    const ImageInfo info{static_cast<const std::uint8_t*>(bytes), size};
    if (H5Pset_driver(fapl, driver, &info) < 0) {
        H5Pclose(fapl);
        return -1;
    }
    return fapl;
}

} // namespace hs::anatomy::detail
