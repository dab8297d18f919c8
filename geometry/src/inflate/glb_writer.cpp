#include <finbook/geometry/inflate/glb_writer.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace finbook::geometry {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF's binary chunk is little-endian");

constexpr int kFloat = 5126;       // glTF componentType FLOAT
constexpr int kUnsignedInt = 5125; // UNSIGNED_INT
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

template <class Number> void appendNumber(std::string &out, Number value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

// A JSON string: quotes, backslashes and control characters escaped, UTF-8 kept as it is.
void appendString(std::string &out, const std::string &text)
{
    out += '"';
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (byte < 0x20) {
            static const char hex[] = "0123456789abcdef";
            out += "\\u00";
            out += hex[byte >> 4];
            out += hex[byte & 15];
        } else {
            out += c;
        }
    }
    out += '"';
}

double linear(double srgb)
{
    const double c = std::clamp(std::isfinite(srgb) ? srgb : 0.0, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

template <class Value> void appendBytes(std::string &bin, Value value)
{
    char bytes[sizeof(Value)];
    std::memcpy(bytes, &value, sizeof(Value));
    bin.append(bytes, sizeof(Value));
}

void appendU32(std::string &out, std::uint32_t value)
{
    appendBytes(out, value);
}

struct View {
    std::size_t offset = 0, length = 0;
    int target = 0;
};

// Appends rows of `matrix` as float32 triples; returns the per-column minimum and maximum of
// the values as written (float), which glTF readers check positions against.
template <class Matrix>
void appendFloatRows(std::string &bin, const Matrix &matrix, float lo[3], float hi[3])
{
    std::fill(lo, lo + 3, std::numeric_limits<float>::max());
    std::fill(hi, hi + 3, std::numeric_limits<float>::lowest());
    for (Eigen::Index r = 0; r < matrix.rows(); ++r)
        for (int c = 0; c < 3; ++c) {
            const auto value = static_cast<float>(matrix(r, c));
            lo[c] = std::min(lo[c], value);
            hi[c] = std::max(hi[c], value);
            appendBytes(bin, value);
        }
}

void appendTriple(std::string &json, const float values[3])
{
    json += '[';
    for (int c = 0; c < 3; ++c) {
        if (c > 0)
            json += ',';
        appendNumber(json, double(values[c])); // exact: readers compare it as a double
    }
    json += ']';
}

struct Parts {
    std::string meshes, materials, nodes, accessors, views, images, textures;
    int imageCount = 0;
};

void addAccessor(Parts &parts, int &accessors, int view, int componentType, std::size_t count,
                 const char *type, const float *lo = nullptr, const float *hi = nullptr)
{
    std::string &json = parts.accessors;
    if (accessors++ > 0)
        json += ',';
    json += "{\"bufferView\":";
    appendNumber(json, view);
    json += ",\"componentType\":";
    appendNumber(json, componentType);
    json += ",\"count\":";
    appendNumber(json, count);
    json += ",\"type\":\"";
    json += type;
    json += '"';
    if (lo && hi) {
        json += ",\"min\":";
        appendTriple(json, lo);
        json += ",\"max\":";
        appendTriple(json, hi);
    }
    json += '}';
}

void addView(Parts &parts, int &views, const View &view)
{
    std::string &json = parts.views;
    if (views++ > 0)
        json += ',';
    json += "{\"buffer\":0,\"byteOffset\":";
    appendNumber(json, view.offset);
    json += ",\"byteLength\":";
    appendNumber(json, view.length);
    if (view.target != 0) { // an image's view has none
        json += ",\"target\":";
        appendNumber(json, view.target);
    }
    json += '}';
}

// `texture`: the index of the object's picture among the textures, or −1 for a flat colour.
void addMaterial(Parts &parts, int index, const GlbObject &object, int texture)
{
    std::string &json = parts.materials;
    if (index > 0)
        json += ',';
    json += "{\"name\":";
    appendString(json, object.name);
    if (texture >= 0) {
        json += ",\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":";
        appendNumber(json, texture);
        json += "},\"metallicFactor\":0,\"roughnessFactor\":1},\"alphaMode\":\"BLEND\"}";
        return;
    }
    json += ",\"pbrMetallicRoughness\":{\"baseColorFactor\":[";
    for (const double c : {linear(object.red), linear(object.green), linear(object.blue)}) {
        appendNumber(json, c);
        json += ',';
    }
    const double opacity =
        std::clamp(std::isfinite(object.opacity) ? object.opacity : 1.0, 0.0, 1.0);
    appendNumber(json, opacity);
    json += "],\"metallicFactor\":0,\"roughnessFactor\":1}";
    if (opacity < 1.0)
        json += ",\"alphaMode\":\"BLEND\"";
    json += '}';
}

// The accessors from `firstAccessor` on: positions, normals, indices, then (`textured`) the
// texture coordinates.
void addMeshAndNode(Parts &parts, int index, const std::string &name, int firstAccessor,
                    bool textured)
{
    if (index > 0) {
        parts.meshes += ',';
        parts.nodes += ',';
    }
    std::string quoted;
    appendString(quoted, name);
    parts.meshes += "{\"name\":" + quoted + ",\"primitives\":[{\"attributes\":{\"POSITION\":" +
                    std::to_string(firstAccessor) +
                    ",\"NORMAL\":" + std::to_string(firstAccessor + 1) +
                    (textured ? ",\"TEXCOORD_0\":" + std::to_string(firstAccessor + 3) : "") +
                    "},\"indices\":" + std::to_string(firstAccessor + 2) +
                    ",\"material\":" + std::to_string(index) + ",\"mode\":4}]}";
    parts.nodes += "{\"name\":" + quoted + ",\"mesh\":" + std::to_string(index) + '}';
}

std::string json(const Parts &parts, int objects, std::size_t binLength)
{
    std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"Finbook\"},"
                       "\"scene\":0,\"scenes\":[{";
    if (objects > 0) {
        json += "\"nodes\":[";
        for (int i = 0; i < objects; ++i) {
            if (i > 0)
                json += ',';
            appendNumber(json, i);
        }
        json += "]}],\"nodes\":[" + parts.nodes + "],\"meshes\":[" + parts.meshes +
                "],\"materials\":[" + parts.materials + "],\"accessors\":[" + parts.accessors +
                (parts.imageCount > 0
                     ? "],\"images\":[" + parts.images + "],\"textures\":[" + parts.textures +
                           "],\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,"
                           "\"wrapS\":33071,\"wrapT\":33071}"
                     : std::string()) +
                "],\"bufferViews\":[" + parts.views + "],\"buffers\":[{\"byteLength\":";
        appendNumber(json, binLength);
        json += "}]}";
    } else {
        json += "}]}";
    }
    return json;
}

} // namespace

std::string glbBytes(const std::vector<GlbObject> &objects)
{
    constexpr std::size_t kMaxBytes = std::numeric_limits<std::uint32_t>::max() - 1024;
    std::size_t needed = 0;
    for (const GlbObject &object : objects)
        needed += std::size_t(object.solid.V.rows()) * 32 +
                  std::size_t(object.solid.F.rows()) * 12 + object.png.size() + 4;
    if (needed > kMaxBytes)
        return {};

    std::string bin;
    bin.reserve(needed);
    Parts parts;
    int written = 0, accessors = 0, views = 0;
    for (const GlbObject &object : objects) {
        const InflatedSolid &solid = object.solid;
        const auto vertices = std::size_t(solid.V.rows());
        if (vertices == 0 || solid.F.rows() == 0 || solid.N.rows() != solid.V.rows())
            continue;
        float lo[3], hi[3], nlo[3], nhi[3];
        const View positions{bin.size(), vertices * 12, kArrayBuffer};
        appendFloatRows(bin, solid.V, lo, hi);
        const View normals{bin.size(), vertices * 12, kArrayBuffer};
        appendFloatRows(bin, solid.N, nlo, nhi);
        const View indices{bin.size(), std::size_t(solid.F.rows()) * 12, kElementArrayBuffer};
        for (Eigen::Index f = 0; f < solid.F.rows(); ++f)
            for (int c = 0; c < 3; ++c)
                appendU32(bin, static_cast<std::uint32_t>(solid.F(f, c)));
        const int firstView = views, firstAccessor = accessors;
        for (const View &view : {positions, normals, indices})
            addView(parts, views, view);
        addAccessor(parts, accessors, firstView, kFloat, vertices, "VEC3", lo, hi);
        addAccessor(parts, accessors, firstView + 1, kFloat, vertices, "VEC3");
        addAccessor(parts, accessors, firstView + 2, kUnsignedInt, indices.length / 4, "SCALAR");
        int texture = -1;
        if (object.textured()) {
            const View uv{bin.size(), vertices * 8, kArrayBuffer};
            for (Eigen::Index r = 0; r < solid.UV.rows(); ++r)
                for (int c = 0; c < 2; ++c)
                    appendBytes(bin, static_cast<float>(solid.UV(r, c)));
            addView(parts, views, uv);
            addAccessor(parts, accessors, views - 1, kFloat, vertices, "VEC2");
            const View image{bin.size(), object.png.size(), 0};
            bin += object.png;
            bin.append((4 - bin.size() % 4) % 4, '\0');
            addView(parts, views, image);
            texture = parts.imageCount++;
            if (texture > 0) {
                parts.images += ',';
                parts.textures += ',';
            }
            parts.images +=
                "{\"bufferView\":" + std::to_string(views - 1) + ",\"mimeType\":\"image/png\"}";
            parts.textures += "{\"sampler\":0,\"source\":" + std::to_string(texture) + '}';
        }
        addMaterial(parts, written, object, texture);
        addMeshAndNode(parts, written, object.name, firstAccessor, texture >= 0);
        ++written;
    }

    std::string text = json(parts, written, bin.size());
    text.append((4 - text.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    const std::size_t total = 12 + 8 + text.size() + (written > 0 ? 8 + bin.size() : 0);
    std::string out;
    out.reserve(total);
    out += "glTF";
    appendU32(out, 2);
    appendU32(out, static_cast<std::uint32_t>(total));
    appendU32(out, static_cast<std::uint32_t>(text.size()));
    out += "JSON";
    out += text;
    if (written > 0) {
        appendU32(out, static_cast<std::uint32_t>(bin.size()));
        out += "BIN";
        out += '\0';
        out += bin;
    }
    return out;
}

} // namespace finbook::geometry
