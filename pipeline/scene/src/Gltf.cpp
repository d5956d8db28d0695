// glTF 2.0 binary export and import of the visual surface with tinygltf.

#include "Gltf.h"

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_INCLUDE_JSON
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace hs::scene::detail {

namespace {

constexpr double kMetresPerMm = 0.001;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kLinear = 9729;
constexpr int kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071;

/// Appends `bytes` to buffer 0 (4-byte aligned) and returns the new buffer view's index.
int addBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
    auto& data = model.buffers[0].data;
    while (data.size() % 4 != 0)
        data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
}

/// A float accessor of `components` per element with per-component min and max (required for POSITION, given
/// for every attribute).
int addFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int components, int type) {
    const int view = addBufferView(model, values.data(), values.size() * sizeof(float), kArrayBuffer);
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = values.size() / static_cast<std::size_t>(components);
    accessor.type = type;
    accessor.minValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
    accessor.maxValues.assign(static_cast<std::size_t>(components), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % static_cast<std::size_t>(components);
        accessor.minValues[c] = std::min(accessor.minValues[c], static_cast<double>(values[i]));
        accessor.maxValues[c] = std::max(accessor.maxValues[c], static_cast<double>(values[i]));
    }
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

int addIndexAccessor(tinygltf::Model& model, const std::vector<Triangle>& triangles) {
    std::vector<std::uint32_t> indices;
    indices.reserve(triangles.size() * 3);
    std::uint32_t lo = std::numeric_limits<std::uint32_t>::max(), hi = 0;
    for (const auto& t : triangles)
        for (const std::int32_t i : t) {
            indices.push_back(static_cast<std::uint32_t>(i));
            lo = std::min(lo, static_cast<std::uint32_t>(i));
            hi = std::max(hi, static_cast<std::uint32_t>(i));
        }
    tinygltf::Accessor accessor;
    accessor.bufferView =
        addBufferView(model, indices.data(), indices.size() * sizeof(std::uint32_t), kElementArrayBuffer);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.count = indices.size();
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.minValues = {static_cast<double>(lo)};
    accessor.maxValues = {static_cast<double>(hi)};
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

/// Adds an embedded PNG image and a texture sampling it; returns the texture index or -1 for no image.
int addTexture(tinygltf::Model& model, const std::string& png, const std::string& name) {
    if (png.empty())
        return -1;
    tinygltf::Image image;
    image.name = name;
    image.mimeType = "image/png";
    image.bufferView = addBufferView(model, png.data(), png.size(), 0);
    model.bufferViews.back().target = 0; // image data: no GPU buffer target
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.sampler = 0;
    texture.source = static_cast<int>(model.images.size() - 1);
    texture.name = name;
    model.textures.push_back(texture);
    return static_cast<int>(model.textures.size() - 1);
}

/// The surface's own normals when it has them (smooth across UV seams), else area-weighted ones of the split mesh.
std::vector<float> unitNormals(const VisualSurface& surface) {
    const auto normals = surface.normals.empty() ? vertexNormals(surface.mesh) : surface.normals;
    std::vector<float> out;
    out.reserve(normals.size() * 3);
    for (const Vec3& n : normals) {
        const double len = std::sqrt(dot(n, n));
        // glTF requires unit normals; an isolated or degenerate vertex gets +Z rather than a zero vector.
        const Vec3 u = len > 0.0 && std::isfinite(len) ? n / len : Vec3{0.0, 0.0, 1.0};
        out.insert(out.end(), {static_cast<float>(u.x), static_cast<float>(u.y), static_cast<float>(u.z)});
    }
    return out;
}

/// Per-vertex tangents (xyz unit, w = handedness) for the normal map, from the UV gradients of the incident
/// triangles (Lengyel's method), orthogonalised against the normal. glTF's V runs downwards while the normal map's
/// +Y is up, so the bitangent follows -V. Triangles with degenerate UVs contribute nothing; a vertex left without a
/// tangent gets any unit vector perpendicular to its normal.
std::vector<float> tangents(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uvs,
                            const std::vector<float>& normals) {
    std::vector<Vec3> t(mesh.vertexCount()), b(mesh.vertexCount());
    for (const auto& tri : mesh.triangles) {
        const auto i0 = static_cast<std::size_t>(tri[0]), i1 = static_cast<std::size_t>(tri[1]),
                   i2 = static_cast<std::size_t>(tri[2]);
        const Vec3 e1 = mesh.points[i1] - mesh.points[i0], e2 = mesh.points[i2] - mesh.points[i0];
        const double du1 = uvs[i1][0] - uvs[i0][0], du2 = uvs[i2][0] - uvs[i0][0];
        const double dv1 = -(uvs[i1][1] - uvs[i0][1]), dv2 = -(uvs[i2][1] - uvs[i0][1]);
        const double r = du1 * dv2 - du2 * dv1;
        if (std::abs(r) < 1e-20)
            continue;
        const Vec3 tangent = (e1 * dv2 - e2 * dv1) / r, bitangent = (e2 * du1 - e1 * du2) / r;
        for (const std::size_t i : {i0, i1, i2}) {
            t[i] += tangent;
            b[i] += bitangent;
        }
    }
    std::vector<float> out;
    out.reserve(mesh.vertexCount() * 4);
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const Vec3 n{normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
        Vec3 u = t[i] - n * dot(n, t[i]);
        double len = std::sqrt(dot(u, u));
        if (!(len > 1e-12)) {
            u = std::abs(n.x) < 0.9 ? cross(n, Vec3{1.0, 0.0, 0.0}) : cross(n, Vec3{0.0, 1.0, 0.0});
            len = std::sqrt(dot(u, u));
        }
        u = u / len;
        const float w = dot(cross(n, u), b[i]) < 0.0 ? -1.0f : 1.0f;
        out.insert(out.end(), {static_cast<float>(u.x), static_cast<float>(u.y), static_cast<float>(u.z), w});
    }
    return out;
}

tinygltf::Material pbrMaterial(int albedo, int normal, int metallicRoughness) {
    tinygltf::Material material;
    material.name = "tissue";
    material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    material.pbrMetallicRoughness.baseColorTexture.index = albedo;
    material.pbrMetallicRoughness.metallicFactor = 0.0; // tissue is a dielectric
    material.pbrMetallicRoughness.roughnessFactor = 1.0;
    material.pbrMetallicRoughness.metallicRoughnessTexture.index = metallicRoughness;
    material.normalTexture.index = normal;
    material.alphaMode = "OPAQUE";
    material.doubleSided = false;
    return material;
}

} // namespace

Result<std::string> encodeGlb(const VisualSurface& surface, const GltfTextures& textures,
                              const std::string& generator) {
    const SurfaceMesh& mesh = surface.mesh;
    if (mesh.faceCount() == 0 || surface.uvs.size() != mesh.vertexCount())
        return fail(ErrorCode::InvalidInput, "surface.glb: need triangles and one UV per point");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = generator;
    model.buffers.resize(1);

    std::vector<float> positions, uvs;
    positions.reserve(mesh.vertexCount() * 3);
    for (const Vec3& p : mesh.points)
        positions.insert(positions.end(),
                         {static_cast<float>(p.x * kMetresPerMm), static_cast<float>(p.y * kMetresPerMm),
                          static_cast<float>(p.z * kMetresPerMm)});
    for (const auto& uv : surface.uvs)
        uvs.insert(uvs.end(), {uv[0], uv[1]});

    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = addFloatAccessor(model, positions, 3, TINYGLTF_TYPE_VEC3);
    const std::vector<float> normals = unitNormals(surface);
    primitive.attributes["NORMAL"] = addFloatAccessor(model, normals, 3, TINYGLTF_TYPE_VEC3);
    if (!textures.normalPng.empty())
        primitive.attributes["TANGENT"] =
            addFloatAccessor(model, tangents(mesh, surface.uvs, normals), 4, TINYGLTF_TYPE_VEC4);
    primitive.attributes["TEXCOORD_0"] = addFloatAccessor(model, uvs, 2, TINYGLTF_TYPE_VEC2);
    primitive.indices = addIndexAccessor(model, mesh.triangles);

    tinygltf::Sampler sampler;
    sampler.magFilter = kLinear;
    sampler.minFilter = kLinearMipmapLinear;
    sampler.wrapS = kClampToEdge; // an atlas: charts must not bleed across the border
    sampler.wrapT = kClampToEdge;
    model.samplers.push_back(sampler);
    const int albedo = addTexture(model, textures.albedoPng, "albedo");
    const int normal = addTexture(model, textures.normalPng, "normal");
    const int metallicRoughness = addTexture(model, textures.metallicRoughnessPng, "metallicRoughness");
    if (model.textures.empty())
        model.samplers.clear();
    model.materials.push_back(pbrMaterial(albedo, normal, metallicRoughness));
    primitive.material = 0;

    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "surface";
    gltfMesh.primitives.push_back(primitive);
    model.meshes.push_back(gltfMesh);
    tinygltf::Node node;
    node.name = "surface";
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene gltfScene;
    gltfScene.name = "hysteroscene";
    gltfScene.nodes = {0};
    model.scenes.push_back(gltfScene);
    model.defaultScene = 0;

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true))
        return fail(ErrorCode::BackendFailure, "surface.glb: tinygltf could not serialize the model");
    return stream.str();
}

namespace {

bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true; // the reader takes the maps from maps/*.png; nothing to decode here
}
bool noFileExists(const std::string&, void*) {
    return false;
}
std::string noExpand(const std::string& path, void*) {
    return path;
}
bool noRead(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err)
        *err += "external file " + path + " refused (a package's GLB must be self-contained)\n";
    return false;
}
bool noWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

/// Copies accessor `index` as floats, checking type, count and bounds.
Result<std::vector<float>> floatAttribute(const tinygltf::Model& model, int index, int type, std::size_t components,
                                          const std::string& name, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        return fail(ErrorCode::InvalidInput, name + ": no " + what + " accessor");
    const auto& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.type != type || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.bufferView < 0 ||
        static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
        return fail(ErrorCode::InvalidInput, name + ": " + what + " must be a float accessor with a buffer view");
    const auto& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::size_t elementBytes = components * sizeof(float);
    const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        return fail(ErrorCode::InvalidInput, name + ": " + what + " refers to a missing buffer");
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (a.count > 0 && (view.byteOffset + a.byteOffset + (a.count - 1) * stride + elementBytes > data.size() ||
                        a.byteOffset + (a.count - 1) * stride + elementBytes > view.byteLength))
        return fail(ErrorCode::InvalidInput, name + ": " + what + " runs past its buffer");
    std::vector<float> out(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i)
        std::memcpy(&out[i * components], data.data() + view.byteOffset + a.byteOffset + i * stride, elementBytes);
    return out;
}

Result<std::vector<Triangle>> triangleIndices(const tinygltf::Model& model, int index, std::size_t vertexCount,
                                              const std::string& name) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        return fail(ErrorCode::InvalidInput, name + ": the primitive has no indices");
    const auto& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || a.type != TINYGLTF_TYPE_SCALAR || a.count % 3 != 0 ||
        a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
        return fail(ErrorCode::InvalidInput, name + ": indices must be unsigned 32-bit triangles");
    const auto& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        return fail(ErrorCode::InvalidInput, name + ": indices refer to a missing buffer");
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset + a.byteOffset + a.count * 4 > data.size() || a.byteOffset + a.count * 4 > view.byteLength)
        return fail(ErrorCode::InvalidInput, name + ": indices run past their buffer");
    std::vector<Triangle> triangles(a.count / 3);
    for (std::size_t i = 0; i < a.count; ++i) {
        std::uint32_t v = 0;
        std::memcpy(&v, data.data() + view.byteOffset + a.byteOffset + i * 4, 4);
        if (v >= vertexCount)
            return fail(ErrorCode::InvalidInput, name + ": index " + std::to_string(v) + " is out of range");
        triangles[i / 3][i % 3] = static_cast<std::int32_t>(v);
    }
    return triangles;
}

} // namespace

Result<GlbSurface> decodeGlb(std::string_view bytes, const std::string& name) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&noFileExists, &noExpand, &noRead, &noWrite, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    if (!loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                     static_cast<unsigned int>(bytes.size()), ""))
        return fail(ErrorCode::InvalidInput, name + ": not a valid glTF binary: " + err.substr(0, 300));
    if (model.meshes.empty() || model.meshes[0].primitives.empty())
        return fail(ErrorCode::InvalidInput, name + ": no mesh primitive");
    const auto& primitive = model.meshes[0].primitives[0];
    const auto attribute = [&](const char* key) {
        const auto it = primitive.attributes.find(key);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    auto positions = floatAttribute(model, attribute("POSITION"), TINYGLTF_TYPE_VEC3, 3, name, "POSITION");
    if (!positions)
        return positions.failure();
    auto uvs = floatAttribute(model, attribute("TEXCOORD_0"), TINYGLTF_TYPE_VEC2, 2, name, "TEXCOORD_0");
    if (!uvs)
        return uvs.failure();
    GlbSurface out;
    const std::size_t n = positions->size() / 3;
    if (uvs->size() / 2 != n)
        return fail(ErrorCode::InvalidInput, name + ": TEXCOORD_0 and POSITION differ in count");
    for (std::size_t i = 0; i < n; ++i) {
        out.points.push_back(Vec3{(*positions)[3 * i], (*positions)[3 * i + 1], (*positions)[3 * i + 2]} /
                             kMetresPerMm);
        out.uvs.push_back({(*uvs)[2 * i], (*uvs)[2 * i + 1]});
    }
    auto triangles = triangleIndices(model, primitive.indices, n, name);
    if (!triangles)
        return triangles.failure();
    out.triangles = std::move(*triangles);
    return out;
}

} // namespace hs::scene::detail
