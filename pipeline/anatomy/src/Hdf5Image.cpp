// A read-only HDF5 file driver over bytes in memory (see Hdf5Image.h for why the project has its own).
#include "Hdf5Image.h"

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

} // namespace

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
