// HDF5 file of the shape model, in statismo's layout (version 0.9, as Scalismo writes and reads it):
//   /version/majorVersion, /version/minorVersion          int
//   /model/mean [3n], /model/pcaBasis [3n][k] (orthonormal), /model/pcaVariance [k], /model/noiseVariance [1]  float
//   /representer (attributes name, datasetType = POLYGON_MESH), /representer/points [3][n] float,
//   /representer/cells [3][m] int
//   /modelinfo/build-time                                  string
// and ours under /hysteroscene: conditioning (regression, residual covariance, feature names, patient ranges),
// template layout and face labels, pose prior, metadata.
#include "hs/anatomy/ShapeModel.h"
#include "hs/io/AtomicFile.h"

#include "Hdf5Image.h"
#include "ShapeModelData.h"

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <type_traits>

namespace hs::anatomy {

namespace {

constexpr int kFormatVersion = 1;
constexpr hsize_t kMaxValues = 200'000'000; ///< refuse datasets above this many values (hostile files)
/// A dataset's values may take at most this many times the bytes it stores (deflate's largest ratio is 1032:1): a
/// count is checked against what the file holds before anything is allocated by it.
constexpr hsize_t kMaxInflation = 1032;
constexpr std::int64_t kMaxFileBytes = std::int64_t{1} << 30; ///< a shape model file larger than 1 GiB is refused

/// Silences HDF5's error printing for the lifetime of the object (we report errors ourselves).
class QuietErrors {
public:
    QuietErrors() {
        H5Eget_auto2(H5E_DEFAULT, &m_func, &m_data);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, m_func, m_data); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t m_func = nullptr;
    void* m_data = nullptr;
};

/// Closes an HDF5 handle with the right function.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t)) : m_id(id), m_close(close) {}
    ~Handle() {
        if (m_id >= 0)
            m_close(m_id);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    hid_t get() const { return m_id; }
    bool valid() const { return m_id >= 0; }

private:
    hid_t m_id;
    herr_t (*m_close)(hid_t);
};

struct Writer {
    hid_t file;
    bool ok = true;

    /// Creation properties without modification times, so the same model gives the same file bytes.
    static hid_t untimed(hid_t propertyClass) {
        const hid_t p = H5Pcreate(propertyClass);
        if (p >= 0)
            H5Pset_obj_track_times(p, 0);
        return p;
    }

    void dataset(const std::string& path, hid_t type, const std::vector<hsize_t>& dims, const void* values) {
        Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
        H5Pset_create_intermediate_group(lcpl.get(), 1);
        Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
        Handle dcpl(untimed(H5P_DATASET_CREATE), H5Pclose);
        Handle set(H5Dcreate2(file, path.c_str(), type, space.get(), lcpl.get(), dcpl.get(), H5P_DEFAULT), H5Dclose);
        ok = ok && set.valid() && H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) >= 0;
    }
    void scalarInt(const std::string& path, int value) {
        Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
        H5Pset_create_intermediate_group(lcpl.get(), 1);
        Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        Handle dcpl(untimed(H5P_DATASET_CREATE), H5Pclose);
        Handle set(H5Dcreate2(file, path.c_str(), H5T_NATIVE_INT, space.get(), lcpl.get(), dcpl.get(), H5P_DEFAULT),
                   H5Dclose);
        ok = ok && set.valid() && H5Dwrite(set.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) >= 0;
    }
    void string(const std::string& path, const std::string& value) {
        Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
        H5Pset_create_intermediate_group(lcpl.get(), 1);
        Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(type.get(), std::max<std::size_t>(1, value.size()));
        Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        Handle dcpl(untimed(H5P_DATASET_CREATE), H5Pclose);
        Handle set(H5Dcreate2(file, path.c_str(), type.get(), space.get(), lcpl.get(), dcpl.get(), H5P_DEFAULT),
                   H5Dclose);
        ok = ok && set.valid() && H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, value.c_str()) >= 0;
    }
    void group(const std::string& path) {
        Handle gcpl(untimed(H5P_GROUP_CREATE), H5Pclose);
        Handle g(H5Gcreate2(file, path.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
        ok = ok && g.valid();
    }
    void attribute(const std::string& object, const std::string& name, const std::string& value) {
        Handle obj(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
        Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(type.get(), std::max<std::size_t>(1, value.size()));
        Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        Handle attr(H5Acreate2(obj.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
        ok = ok && attr.valid() && H5Awrite(attr.get(), type.get(), value.c_str()) >= 0;
    }
};

using RowMajorF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMajorD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& s : items)
        out += (out.empty() ? "" : "\n") + s;
    return out;
}

void writeModel(Writer& w, const ShapeModel::Data& d) {
    const auto n = static_cast<hsize_t>(d.reference.points.size());
    const auto m = static_cast<hsize_t>(d.reference.triangles.size());
    const auto k = static_cast<hsize_t>(d.variance.size());
    w.scalarInt("/version/majorVersion", 0);
    w.scalarInt("/version/minorVersion", 9);
    const Eigen::VectorXf mean = d.mean.cast<float>();
    w.dataset("/model/mean", H5T_NATIVE_FLOAT, {3 * n}, mean.data());
    const RowMajorF basis = d.basis.cast<float>();
    w.dataset("/model/pcaBasis", H5T_NATIVE_FLOAT, {3 * n, k}, basis.data());
    const Eigen::VectorXf variance = d.variance.cast<float>();
    w.dataset("/model/pcaVariance", H5T_NATIVE_FLOAT, {k}, variance.data());
    const float noise = static_cast<float>(d.noiseVariance);
    w.dataset("/model/noiseVariance", H5T_NATIVE_FLOAT, {1}, &noise);

    RowMajorF points(3, static_cast<Eigen::Index>(n));
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(n); ++i)
        for (int c = 0; c < 3; ++c)
            points(c, i) = static_cast<float>(d.mean(3 * i + c));
    std::vector<std::int32_t> cells(3 * m);
    for (std::size_t f = 0; f < m; ++f)
        for (std::size_t c = 0; c < 3; ++c)
            cells[c * m + f] = d.reference.triangles[f][c];
    w.dataset("/representer/points", H5T_NATIVE_FLOAT, {3, n}, points.data());
    w.dataset("/representer/cells", H5T_NATIVE_INT32, {3, m}, cells.data());
    w.attribute("/representer", "name", "hysteroscene::anatomy uterus template");
    w.attribute("/representer", "datasetType", "POLYGON_MESH");
    w.string("/modelinfo/build-time", "not recorded (the build is deterministic; see /hysteroscene)");
}

void writeOurs(Writer& w, const ShapeModel::Data& d) {
    w.group("/hysteroscene");
    w.attribute("/hysteroscene", "formatVersion", std::to_string(kFormatVersion));
    w.attribute("/hysteroscene", "description", d.description);
    w.attribute("/hysteroscene", "cohortSeed", std::to_string(d.cohortSeed));
    w.attribute("/hysteroscene", "trainingSize", std::to_string(d.trainingSize));
    w.scalarInt("/hysteroscene/trainingSize", d.trainingSize);
    const double totals[2] = {d.totalVariance, d.noiseVariance};
    w.dataset("/hysteroscene/variance", H5T_NATIVE_DOUBLE, {2}, totals);
    if (d.conditioned) {
        const RowMajorD reg = d.regression;
        w.dataset("/hysteroscene/conditioning/regression", H5T_NATIVE_DOUBLE,
                  {static_cast<hsize_t>(reg.rows()), static_cast<hsize_t>(reg.cols())}, reg.data());
        const RowMajorD cov = d.residualCovariance;
        w.dataset("/hysteroscene/conditioning/residualCovariance", H5T_NATIVE_DOUBLE,
                  {static_cast<hsize_t>(cov.rows()), static_cast<hsize_t>(cov.cols())}, cov.data());
        w.attribute("/hysteroscene/conditioning", "featureNames", join(conditioningFeatureNames()));
        std::vector<double> ranges;
        std::vector<std::string> names;
        for (const auto& r : supportedPatientRanges()) {
            ranges.push_back(r.min);
            ranges.push_back(r.max);
            names.push_back(r.name + " [" + r.unit + "]");
        }
        w.dataset("/hysteroscene/conditioning/patientRanges", H5T_NATIVE_DOUBLE, {ranges.size() / 2, 2}, ranges.data());
        w.attribute("/hysteroscene/conditioning/patientRanges", "names", join(names));
    }
    const auto& p = d.pose;
    const double pose[5] = {p.retroversionProbability, p.antevertedMeanDeg, p.antevertedSdDeg, p.retrovertedMeanDeg,
                            p.retrovertedSdDeg};
    w.dataset("/hysteroscene/pose", H5T_NATIVE_DOUBLE, {5}, pose);
    w.attribute("/hysteroscene/pose", "fields",
                "retroversionProbability antevertedMeanDeg antevertedSdDeg retrovertedMeanDeg retrovertedSdDeg");
    if (d.layout) {
        const auto& l = *d.layout;
        const std::int32_t layout[6] = {l.around, l.outerRings, l.osRings, l.canalRings, l.cavityRings, l.capRings};
        w.dataset("/hysteroscene/template/layout", H5T_NATIVE_INT32, {6}, layout);
        w.attribute("/hysteroscene/template/layout", "fields",
                    "around outerRings osRings canalRings cavityRings capRings");
    }
    for (const auto& [name, values] : d.reference.faceLabels)
        if (!values.empty())
            w.dataset("/hysteroscene/template/faceLabels/" + name, H5T_NATIVE_INT32, {values.size()}, values.data());
}

/// Reads datasets from an open file. A failed lookup is not taken for an absent object: once HDF5 has reported an
/// error on the file, the file is `damaged` and the reader calls HDF5 no more (HDF5 1.10 may leave its metadata
/// cache broken after a failed allocation, and the next call on the file then writes through a null pointer).
struct Reader {
    hid_t file;
    std::string path;
    mutable std::optional<std::string> damaged; ///< what failed first, once HDF5 has failed on the file

    bool exists(const std::string& object) const {
        if (damaged)
            return false;
        std::string prefix;
        std::stringstream parts(object);
        std::string part;
        while (std::getline(parts, part, '/')) {
            if (part.empty())
                continue;
            prefix += "/" + part;
            const htri_t found = H5Lexists(file, prefix.c_str(), H5P_DEFAULT);
            if (found < 0)
                damaged = path + ": cannot look up " + prefix + " (a damaged HDF5 file)";
            if (found <= 0)
                return false;
        }
        return true;
    }

    template <class T>
    Result<std::vector<T>> read(const std::string& object, hid_t type, std::vector<hsize_t>& dims) const {
        if (!exists(object))
            return fail(ErrorCode::InvalidInput, damaged ? *damaged : path + ": missing dataset " + object);
        Handle set(H5Dopen2(file, object.c_str(), H5P_DEFAULT), H5Dclose);
        Handle space(H5Dget_space(set.get()), H5Sclose);
        const int rank = H5Sget_simple_extent_ndims(space.get());
        if (!set.valid() || rank < 0 || rank > 2) {
            damaged = path + ": dataset " + object + " is not a vector or matrix";
            return fail(ErrorCode::InvalidInput, *damaged);
        }
        dims.assign(static_cast<std::size_t>(rank), 0);
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        hsize_t total = 1;
        for (const auto d : dims)
            total *= d;
        if (total > kMaxValues)
            return fail(ErrorCode::LimitExceeded, path + ": dataset " + object + " is too large");
        // What the dataset stores must be in the file and account for its values (compressed, at most
        // kMaxInflation times over): a forged extent in a small file cannot make the reader allocate gigabytes.
        const hsize_t stored = H5Dget_storage_size(set.get());
        hsize_t fileBytes = 0;
        if (H5Fget_filesize(file, &fileBytes) < 0)
            fileBytes = 0;
        if (total > 0 && (stored == 0 || stored > fileBytes || total > stored / sizeof(T) * kMaxInflation + 1))
            return fail(ErrorCode::InvalidInput, path + ": dataset " + object + " declares " + std::to_string(total) +
                                                     " values but stores " + std::to_string(stored) + " bytes of a " +
                                                     std::to_string(fileBytes) + "-byte file (at most " +
                                                     std::to_string(kMaxInflation) + " values a stored value)");
        // The values' type in the file: HDF5 converts each value through a buffer of the file type's size, so a
        // forged 4 GB "float" would have it allocate gigabytes. Numbers of 1 to 8 bytes, of the class asked for.
        Handle fileType(H5Dget_type(set.get()), H5Tclose);
        const H5T_class_t wanted = std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
        const std::size_t typeBytes = fileType.valid() ? H5Tget_size(fileType.get()) : 0;
        if (!fileType.valid() || H5Tget_class(fileType.get()) != wanted || typeBytes < 1 || typeBytes > 8)
            return fail(ErrorCode::InvalidInput,
                        path + ": dataset " + object + " holds values of " + std::to_string(typeBytes) + " bytes" +
                            (fileType.valid() && H5Tget_class(fileType.get()) != wanted
                                 ? std::string(", not ") + (wanted == H5T_FLOAT ? "floating-point" : "integer")
                                 : std::string()) +
                            " (allowed: " + (wanted == H5T_FLOAT ? "floating-point" : "integer") +
                            " numbers of 1 to 8 bytes)");
        std::vector<T> values(static_cast<std::size_t>(total));
        if (H5Dread(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
            damaged = path + ": cannot read dataset " + object;
            return fail(ErrorCode::InvalidInput, *damaged);
        }
        return values;
    }
};

Status expectDims(const std::string& path, const std::string& object, const std::vector<hsize_t>& dims,
                  const std::vector<hsize_t>& expected) {
    if (dims == expected)
        return {};
    std::ostringstream out;
    out << path << ": dataset " << object << " has shape [";
    for (std::size_t i = 0; i < dims.size(); ++i)
        out << (i ? "," : "") << dims[i];
    out << "], expected [";
    for (std::size_t i = 0; i < expected.size(); ++i)
        out << (i ? "," : "") << expected[i];
    out << "]";
    return fail(ErrorCode::InvalidInput, out.str());
}

template <class T>
Status allFinite(const std::string& path, const std::string& object, const std::vector<T>& v) {
    for (const auto x : v)
        if (!std::isfinite(static_cast<double>(x)))
            return fail(ErrorCode::InvalidInput, path + ": dataset " + object + " holds a non-finite value");
    return {};
}

Result<std::shared_ptr<ShapeModel::Data>> readModel(const Reader& r) {
    auto d = std::make_shared<ShapeModel::Data>();
    std::vector<hsize_t> dims;
    auto points = r.read<float>("/representer/points", H5T_NATIVE_FLOAT, dims);
    if (!points)
        return points.failure();
    if (dims.size() != 2 || dims[0] != 3 || dims[1] < 3)
        return fail(ErrorCode::InvalidInput, r.path + ": /representer/points must be [3][n]");
    const hsize_t n = dims[1];
    auto cells = r.read<std::int32_t>("/representer/cells", H5T_NATIVE_INT32, dims);
    if (!cells)
        return cells.failure();
    if (dims.size() != 2 || dims[0] != 3)
        return fail(ErrorCode::InvalidInput, r.path + ": /representer/cells must be [3][m] (triangles)");
    const hsize_t m = dims[1];
    auto mean = r.read<float>("/model/mean", H5T_NATIVE_FLOAT, dims);
    if (!mean)
        return mean.failure();
    HS_TRY(expectDims(r.path, "/model/mean", dims, {3 * n}));
    auto basis = r.read<float>("/model/pcaBasis", H5T_NATIVE_FLOAT, dims);
    if (!basis)
        return basis.failure();
    if (dims.size() != 2 || dims[0] != 3 * n)
        return fail(ErrorCode::InvalidInput, r.path + ": /model/pcaBasis must be [3n][k]");
    const hsize_t k = dims[1];
    auto variance = r.read<float>("/model/pcaVariance", H5T_NATIVE_FLOAT, dims);
    if (!variance)
        return variance.failure();
    HS_TRY(expectDims(r.path, "/model/pcaVariance", dims, {k}));
    auto noise = r.read<float>("/model/noiseVariance", H5T_NATIVE_FLOAT, dims);
    if (!noise)
        return noise.failure();
    HS_TRY(allFinite(r.path, "/representer/points", *points));
    HS_TRY(allFinite(r.path, "/model/mean", *mean));
    HS_TRY(allFinite(r.path, "/model/pcaBasis", *basis));
    HS_TRY(allFinite(r.path, "/model/pcaVariance", *variance));
    for (const float v : *variance)
        if (v < 0.0f)
            return fail(ErrorCode::InvalidInput, r.path + ": /model/pcaVariance holds a negative variance");

    d->reference.points.resize(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < n; ++i)
        d->reference.points[i] = {(*mean)[3 * i], (*mean)[3 * i + 1], (*mean)[3 * i + 2]};
    d->reference.triangles.resize(static_cast<std::size_t>(m));
    for (std::size_t f = 0; f < m; ++f)
        for (std::size_t c = 0; c < 3; ++c)
            d->reference.triangles[f][c] = (*cells)[c * m + f];
    HS_TRY(validate(d->reference));
    d->mean = Eigen::Map<const Eigen::VectorXf>(mean->data(), static_cast<Eigen::Index>(3 * n)).cast<double>();
    d->basis =
        Eigen::Map<const RowMajorF>(basis->data(), static_cast<Eigen::Index>(3 * n), static_cast<Eigen::Index>(k))
            .cast<double>();
    d->variance = Eigen::Map<const Eigen::VectorXf>(variance->data(), static_cast<Eigen::Index>(k)).cast<double>();
    d->noiseVariance = noise->empty() ? 0.0 : static_cast<double>(noise->front());
    d->totalVariance = d->variance.sum();
    return d;
}

Status readOurs(const Reader& r, ShapeModel::Data& d) {
    if (!r.exists("/hysteroscene"))
        return {};
    std::vector<hsize_t> dims;
    const auto k = static_cast<hsize_t>(d.variance.size());
    if (r.exists("/hysteroscene/trainingSize")) {
        auto n = r.read<std::int32_t>("/hysteroscene/trainingSize", H5T_NATIVE_INT32, dims);
        if (!n || n->size() != 1)
            return fail(ErrorCode::InvalidInput, r.path + ": /hysteroscene/trainingSize must be one integer");
        d.trainingSize = n->front();
    }
    if (r.exists("/hysteroscene/variance")) {
        auto v = r.read<double>("/hysteroscene/variance", H5T_NATIVE_DOUBLE, dims);
        if (!v)
            return v.failure();
        HS_TRY(expectDims(r.path, "/hysteroscene/variance", dims, {2}));
        d.totalVariance = (*v)[0];
        d.noiseVariance = (*v)[1];
    }
    if (r.exists("/hysteroscene/conditioning")) {
        const auto p = static_cast<hsize_t>(conditioningFeatureNames().size());
        auto reg = r.read<double>("/hysteroscene/conditioning/regression", H5T_NATIVE_DOUBLE, dims);
        if (!reg)
            return reg.failure();
        HS_TRY(expectDims(r.path, "/hysteroscene/conditioning/regression", dims, {p, k}));
        auto cov = r.read<double>("/hysteroscene/conditioning/residualCovariance", H5T_NATIVE_DOUBLE, dims);
        if (!cov)
            return cov.failure();
        HS_TRY(expectDims(r.path, "/hysteroscene/conditioning/residualCovariance", dims, {k, k}));
        HS_TRY(allFinite(r.path, "/hysteroscene/conditioning/regression", *reg));
        HS_TRY(allFinite(r.path, "/hysteroscene/conditioning/residualCovariance", *cov));
        const auto pi = static_cast<Eigen::Index>(p), ki = static_cast<Eigen::Index>(k);
        d.regression = Eigen::Map<const RowMajorD>(reg->data(), pi, ki);
        d.residualCovariance = Eigen::Map<const RowMajorD>(cov->data(), ki, ki);
        d.residualFactor = detail::choleskyFactor(d.residualCovariance);
        d.conditioned = true;
    }
    if (r.exists("/hysteroscene/pose")) {
        auto pose = r.read<double>("/hysteroscene/pose", H5T_NATIVE_DOUBLE, dims);
        if (!pose)
            return pose.failure();
        HS_TRY(expectDims(r.path, "/hysteroscene/pose", dims, {5}));
        const auto& v = *pose;
        d.pose = PosePrior{v[0], v[1], v[2], v[3], v[4]};
    }
    if (r.exists("/hysteroscene/template/layout")) {
        auto l = r.read<std::int32_t>("/hysteroscene/template/layout", H5T_NATIVE_INT32, dims);
        if (!l)
            return l.failure();
        HS_TRY(expectDims(r.path, "/hysteroscene/template/layout", dims, {6}));
        const auto& v = *l;
        // Each count in range first; the totals in 64 bits (the counts are the file's: their sum may not fit an int).
        std::int64_t rings = 0;
        for (std::size_t i = 0; i < 6; ++i) {
            if (v[i] < 1 || v[i] > 100000)
                return fail(ErrorCode::InvalidInput, r.path + ": /hysteroscene/template/layout value " +
                                                         std::to_string(i) + " is " + std::to_string(v[i]) +
                                                         ", outside 1-100000");
            if (i > 0)
                rings += v[i];
        }
        const std::int64_t around = v[0];
        if (around < 4 || 2 + rings * around != static_cast<std::int64_t>(d.reference.points.size()) ||
            2 * around * rings != static_cast<std::int64_t>(d.reference.triangles.size()))
            return fail(ErrorCode::InvalidInput, r.path + ": /hysteroscene/template/layout does not match the mesh");
        const TemplateLayout layout{v[0], v[1], v[2], v[3], v[4], v[5]};
        d.layout = layout;
    }
    const std::string tissue = std::string("/hysteroscene/template/faceLabels/") + clinical::kSurfaceTissueLabel;
    if (r.exists(tissue)) {
        auto labels = r.read<std::int32_t>(tissue, H5T_NATIVE_INT32, dims);
        if (!labels)
            return labels.failure();
        HS_TRY(expectDims(r.path, tissue, dims, {static_cast<hsize_t>(d.reference.triangles.size())}));
        d.reference.faceLabels[clinical::kSurfaceTissueLabel] = std::move(labels).value();
    }
    return {};
}

} // namespace

Status saveShapeModel(const ShapeModel& model, const std::string& path) {
    if (model.empty())
        return fail(ErrorCode::InvalidInput, "cannot save an empty shape model");
    const QuietErrors quiet;
    const std::string temporary = path + ".part";
    {
        Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        if (!file.valid())
            return fail(ErrorCode::IoError, "cannot create " + temporary);
        Writer w{file.get()};
        writeModel(w, model.data());
        writeOurs(w, model.data());
        if (!w.ok) {
            std::remove(temporary.c_str());
            return fail(ErrorCode::IoError, "writing " + temporary + " failed");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::remove(temporary.c_str());
        return fail(ErrorCode::IoError, "cannot rename " + temporary + " to " + path + ": " + ec.message());
    }
    return {};
}

namespace {

/// Reads the model from an open HDF5 file; `name` names it in errors (also in those of the checks on the data,
/// such as the reference mesh's validation, which do not know the file).
Result<ShapeModel> readShapeModelFile(hid_t file, const std::string& name) {
    const auto named = [&name](const Error& e) {
        return fail(e.code, e.detail.find(name) == std::string::npos ? name + ": " + e.detail : e.detail);
    };
    const Reader reader{file, name, std::nullopt};
    auto data = readModel(reader);
    if (reader.damaged)
        return fail(ErrorCode::InvalidInput, *reader.damaged);
    if (!data)
        return named(data.error());
    Status ours = readOurs(reader, **data);
    if (reader.damaged)
        return fail(ErrorCode::InvalidInput, *reader.damaged);
    if (!ours.ok())
        return named(ours.error());
    return ShapeModel(std::shared_ptr<const ShapeModel::Data>(std::move(data).value()));
}

} // namespace

Result<ShapeModel> loadShapeModel(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return fail(ErrorCode::NotFound, "shape model file " + path + " does not exist");
    // Read whole (the models are megabytes), then through the same in-memory driver as an image.
    auto bytes = io::readFile(path, kMaxFileBytes);
    if (!bytes)
        return bytes.failure();
    return loadShapeModelImage(bytes->data(), bytes->size(), path);
}

Result<ShapeModel> loadShapeModelImage(const void* bytes, std::size_t size, const std::string& name) {
    const QuietErrors quiet;
    if (!bytes || size == 0)
        return fail(ErrorCode::InvalidInput, name + " is empty, not an HDF5 file");
    // HDF5 reads the bytes through the project's read-only driver (detail::hdf5ImageAccess): never written, never
    // copied, and no metadata accumulator, whose HDF5 1.10 code crashes on some damaged files.
    if (const std::string damage = detail::findHdf5ImageDamage(bytes, size); !damage.empty())
        return fail(ErrorCode::InvalidInput, name + ": " + damage + " (a damaged HDF5 file)");
    Handle fapl(detail::hdf5ImageAccess(bytes, size), H5Pclose);
    if (!fapl.valid())
        return fail(ErrorCode::BackendFailure, name + ": HDF5 cannot take the file image");
    Handle file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
    if (!file.valid())
        return fail(ErrorCode::InvalidInput, name + " is not an HDF5 file (or a damaged one)");
    return readShapeModelFile(file.get(), name);
}

} // namespace hs::anatomy
