// Design note. The Open Asset Import Library parses every format; two things are checked around
// it. Before: a header that announces more elements than the file can hold (a PLY's or an OFF's
// counts) is refused, since the library would reserve room for them all (10^8 faces announced in a
// 300-byte PLY took 1.5 GB and 12 s, an OFF then aborted the process). After: an OBJ's vertices
// come out of the library one per face corner, in face order; the file's own order (its `v`
// records, which a point cache must follow for the modeller that reads the same file) is found
// again by matching each vertex to the record at its position.

#include "mesh_file.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <unordered_map>
#include <vector>

namespace io {

namespace {

using namespace Qt::Literals::StringLiterals;

// bytes of the header a count check reads at most
constexpr qint64 kHeaderBytes = 64 * 1024;

QString shownMeshPath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// the bytes one value of a PLY property type takes in a binary file (0: not a type)
int plyTypeBytes(const QByteArray &type)
{
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
        return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
        return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
        return 4;
    if (type == "double" || type == "float64")
        return 8;
    return 0;
}

// why a PLY's header announces more than its body can hold; empty when it does not
QString plyCountProblem(const QByteArray &head, qint64 fileSize)
{
    const qsizetype end = head.indexOf("end_header");
    if (end < 0)
        return {};  // the library says what is wrong with a header it cannot read
    const qsizetype bodyStart = head.indexOf('\n', end);
    const qint64 body = fileSize - (bodyStart < 0 ? head.size() : bodyStart + 1);
    bool binary = false;
    struct Element {
        QByteArray name;
        qint64 count = 0;
        qint64 minBytes = 0;
    };
    std::vector<Element> elements;
    for (const QByteArray &line : head.left(end).split('\n')) {
        const QList<QByteArray> words = line.simplified().split(' ');
        if (words.size() >= 2 && words[0] == "format")
            binary = words[1] != "ascii";
        else if (words.size() >= 3 && words[0] == "element") {
            bool ok = false;
            const qint64 count = words[2].toLongLong(&ok);
            if (!ok || count < 0)
                return u"its header's element \"%1\" has no count it can hold"_s.arg(QString::fromLatin1(words[1]));
            elements.push_back({words[1], count, 0});
        } else if (words.size() >= 3 && words[0] == "property" && !elements.empty()) {
            // a list may be empty: its count alone; ASCII: a digit and a space at least
            const bool list = words[1] == "list";
            elements.back().minBytes += binary ? plyTypeBytes(list ? words[2] : words[1]) : 2;
        }
    }
    qint64 needed = 0;
    for (const Element &e : elements) {
        if (e.count > kMaxMeshElements)
            return u"its header announces %1 elements \"%2\", more than the limit of %3"_s.arg(e.count).arg(
                QString::fromLatin1(e.name)).arg(kMaxMeshElements);
        needed += e.count * std::max<qint64>(1, e.minBytes);
    }
    if (needed > body)
        return u"its header announces more than it holds (at least %1 bytes of elements, in %2 bytes): it is "
               "truncated or damaged"_s.arg(needed).arg(body);
    return {};
}

// why an OFF's counts are more than its text can hold; empty when they are not
QString offCountProblem(const QByteArray &head, qint64 fileSize)
{
    QList<QByteArray> words;
    for (const QByteArray &line : head.split('\n')) {
        const qsizetype hash = line.indexOf('#');
        const QByteArray text = (hash < 0 ? line : line.left(hash)).simplified();
        if (!text.isEmpty())
            words += text.split(' ');
        if (words.size() >= 4)
            break;
    }
    if (words.size() < 4 || !words[0].endsWith("OFF") || words.contains("BINARY"))
        return {};
    bool okV = false, okF = false;
    const qint64 vertices = words[1].toLongLong(&okV), faces = words[2].toLongLong(&okF);
    if (!okV || !okF || vertices < 0 || faces < 0)
        return u"its header's counts are not whole numbers"_s;
    if (vertices > kMaxMeshElements || faces > kMaxMeshElements)
        return u"its header announces %1 vertices and %2 faces, more than the limit of %3"_s.arg(vertices).arg(faces).arg(
            kMaxMeshElements);
    // "0 0 0\n" a vertex, "3 0 1 2\n" a face, at the least
    if (6 * vertices + 8 * faces > fileSize)
        return u"its header announces %1 vertices and %2 faces, more than its %3 bytes hold: it is truncated or "
               "damaged"_s.arg(vertices).arg(faces).arg(fileSize);
    return {};
}

// an OBJ's `v` records, in order; false when one cannot be read as three numbers
bool objVertexRecords(const QString &path, std::vector<Eigen::Vector3d> &records)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine();
        if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t'))
            continue;
        const char *at = line.constData() + 2;
        Eigen::Vector3d v;
        for (int a = 0; a < 3; ++a) {
            char *end = nullptr;
            v[a] = std::strtod(at, &end);
            if (end == at)
                return false;
            at = end;
        }
        records.push_back(v);
    }
    return true;
}

struct FloatKey {
    float x, y, z;
    bool operator==(const FloatKey &o) const { return x == o.x && y == o.y && z == o.z; }
};
struct FloatKeyHash {
    std::size_t operator()(const FloatKey &k) const
    {
        const auto bits = [](float f) {
            std::uint32_t u;
            std::memcpy(&u, &f, sizeof u);
            return std::size_t(u);
        };
        return bits(k.x) * 73856093u ^ bits(k.y) * 19349663u ^ bits(k.z) * 83492791u;
    }
};

// the records near each point: a grid of cells `cell` wide, so that a point finds the records
// within `cell` of it in its own cell and the 26 around it
class RecordGrid {
public:
    RecordGrid(const std::vector<Eigen::Vector3d> &records, double cell) : m_records(records), m_cell(cell)
    {
        m_cells.reserve(records.size());
        for (std::size_t r = 0; r < records.size(); ++r)
            m_cells[keyOf(records[r])].push_back(int(r));
    }

    // the nearest record within the cell's width of p; -1 when none is
    int nearest(const Eigen::Vector3d &p) const
    {
        const Key centre = keyOf(p);
        int best = -1;
        double bestDistance = m_cell;
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = m_cells.find(Key{centre.x + dx, centre.y + dy, centre.z + dz});
                    if (it == m_cells.end())
                        continue;
                    for (const int r : it->second) {
                        const double distance = (m_records[std::size_t(r)] - p).lpNorm<Eigen::Infinity>();
                        if (distance <= bestDistance) {
                            best = r;
                            bestDistance = distance;
                        }
                    }
                }
        return best;
    }

private:
    struct Key {
        std::int64_t x, y, z;
        bool operator==(const Key &) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key &k) const
        {
            return std::size_t(k.x) * 73856093u ^ std::size_t(k.y) * 19349663u ^ std::size_t(k.z) * 83492791u;
        }
    };
    Key keyOf(const Eigen::Vector3d &p) const
    {
        return {std::int64_t(std::floor(p.x() / m_cell)), std::int64_t(std::floor(p.y() / m_cell)),
                std::int64_t(std::floor(p.z() / m_cell))};
    }

    const std::vector<Eigen::Vector3d> &m_records;
    double m_cell;
    std::unordered_map<Key, std::vector<int>, KeyHash> m_cells;
};

// the mesh over the OBJ's own records: each vertex the library made is the record at its position;
// false (the mesh unchanged) when one is at no record's position. The library reads numbers with
// a parser of its own that is not correctly rounded ("0.07" can come out a float's last bit off
// strtod's), so a vertex at no record's exact position takes the nearest record within a
// millionth of the file's largest coordinate or extent (a few of a float's last bits)
bool inObjOrder(const QString &path, core::TriangleMesh &mesh)
{
    std::vector<Eigen::Vector3d> records;
    if (!objVertexRecords(path, records) || records.empty())
        return false;
    std::unordered_map<FloatKey, int, FloatKeyHash> recordAt;
    recordAt.reserve(records.size());
    Eigen::Vector3d low = records.front(), high = records.front();
    for (std::size_t r = 0; r < records.size(); ++r) {
        recordAt.emplace(FloatKey{float(records[r].x()), float(records[r].y()), float(records[r].z())}, int(r));
        low = low.cwiseMin(records[r]);
        high = high.cwiseMax(records[r]);
    }
    const double scale = std::max({(high - low).maxCoeff(), low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff()});
    std::optional<RecordGrid> grid;  // made at the first vertex that needs it
    std::vector<int> recordOf(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Eigen::Vector3d &p = mesh.vertices[v];
        const auto it = recordAt.find(FloatKey{float(p.x()), float(p.y()), float(p.z())});
        if (it != recordAt.end()) {
            recordOf[v] = it->second;
            continue;
        }
        if (!(scale > 0.0) || !std::isfinite(scale))
            return false;
        if (!grid)
            grid.emplace(records, 1e-6 * scale);
        recordOf[v] = grid->nearest(p);
        if (recordOf[v] < 0)
            return false;
    }
    for (std::array<int, 3> &f : mesh.faces)
        for (int &v : f)
            v = recordOf[std::size_t(v)];
    // the records as the library read them, where it did (the same float)
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        records[std::size_t(recordOf[v])] = mesh.vertices[v];
    mesh.vertices = std::move(records);
    return true;
}

// every mesh of the node and its children, placed by their transforms
void collect(const aiScene &scene, const aiNode &node, const aiMatrix4x4 &parent, core::TriangleMesh &out,
             qint64 &leftOut, bool &moved)
{
    const aiMatrix4x4 transform = parent * node.mTransformation;
    moved = moved || !transform.IsIdentity();
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        const aiMesh &mesh = *scene.mMeshes[node.mMeshes[m]];
        const int base = int(out.vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            out.vertices.emplace_back(double(p.x), double(p.y), double(p.z));
        }
        std::vector<Eigen::Vector3d> corners;
        std::vector<std::array<int, 3>> split;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace &face = mesh.mFaces[f];
            if (face.mNumIndices < 3) {
                ++leftOut;
                continue;
            }
            if (face.mNumIndices == 3) {
                out.faces.push_back({base + int(face.mIndices[0]), base + int(face.mIndices[1]), base + int(face.mIndices[2])});
                continue;
            }
            // a polygon split here: the library's own split fans a concave outline over its notch
            corners.clear();
            for (unsigned c = 0; c < face.mNumIndices; ++c)
                corners.push_back(out.vertices[std::size_t(base) + face.mIndices[c]]);
            split.clear();
            core::triangulatePolygon(corners, split);
            for (const std::array<int, 3> &t : split)
                out.faces.push_back({base + int(face.mIndices[t[0]]), base + int(face.mIndices[t[1]]),
                                     base + int(face.mIndices[t[2]])});
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        collect(scene, *node.mChildren[c], transform, out, leftOut, moved);
}

}  // namespace

MeshReadResult readMeshFile(const QString &path)
{
    MeshReadResult result;
    const QString name = shownMeshPath(path);
    const auto fail = [&](const QString &why) {
        result.error = name + u": "_s + why;
        return result;
    };
    const QFileInfo info(path);
    if (!info.exists())
        return fail(u"no such file"_s);
    if (!info.isFile())
        return fail(u"not a file"_s);
    if (info.size() == 0)
        return fail(u"the file is empty"_s);
    if (info.size() > kMaxMeshFileBytes)
        return fail(u"the file is too large: %1 bytes, more than the limit of %2"_s.arg(info.size()).arg(kMaxMeshFileBytes));

    // the counts a header announces, before the library reserves room for them
    {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return fail(u"cannot open: "_s + file.errorString());
        const QByteArray head = file.read(kHeaderBytes);
        QString problem;
        if (head.startsWith("ply"))
            problem = plyCountProblem(head, info.size());
        else if (head.trimmed().startsWith("OFF") || head.mid(1, 3) == "OFF" || head.mid(2, 3) == "OFF")
            problem = offCountProblem(head, info.size());
        if (!problem.isEmpty())
            return fail(problem);
    }

    Assimp::Importer importer;
    // only what is needed: the file's polygons as they are (split in collect), their vertices as the
    // file has them
    const aiScene *scene = nullptr;
    try {
        scene = importer.ReadFile(QFile::encodeName(path).constData(), aiProcess_ValidateDataStructure);
    } catch (const std::bad_alloc &) {
        return fail(u"out of memory while reading it"_s);
    } catch (const std::exception &e) {
        return fail(u"cannot read it as a mesh: "_s + QString::fromUtf8(e.what()));
    }
    if (!scene) {
        const QString why = QString::fromUtf8(importer.GetErrorString());
        if (why.contains(u"mNumMeshes is 0"_s))
            return fail(u"the file holds no mesh: no triangles"_s);
        if (why.contains(u"No suitable reader"_s))
            return fail(u"not a mesh file this build reads (by its contents and its extension); meshes are read "
                        "from "_s + meshFileFilter());
        return fail(u"cannot read it as a mesh: "_s + why + u" (is it truncated or damaged?)"_s);
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0)
        return fail(u"the file holds no mesh"_s);

    core::TriangleMesh mesh;
    qint64 leftOut = 0;
    bool moved = false;
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), mesh, leftOut, moved);
    if (mesh.faces.empty())
        return fail(leftOut > 0 ? u"the mesh has no triangles: only %1 points and lines"_s.arg(leftOut)
                                : u"the mesh has no faces"_s);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!mesh.vertices[v].allFinite())
            return fail(u"vertex %1 has a coordinate that is not a finite number (%2, %3, %4)"_s.arg(v)
                            .arg(mesh.vertices[v].x())
                            .arg(mesh.vertices[v].y())
                            .arg(mesh.vertices[v].z()));
    if (leftOut > 0)
        result.notes << name + u": %1 points and lines left out (a body is made of triangles)"_s.arg(leftOut);

    // an OBJ in the order of its own records
    if (info.suffix().compare(u"obj"_s, Qt::CaseInsensitive) == 0 && !moved && !inObjOrder(path, mesh))
        result.notes << name + u": its vertices could not be matched to its v records: they are in the order the "
                               "importer gives (one per face corner)"_s;
    result.mesh = std::move(mesh);
    return result;
}

QString meshFileFilter()
{
    static const QString filter = [] {
        Assimp::Importer importer;
        std::string list;
        importer.GetExtensionList(list);  // "*.3ds;*.obj;..."
        return QString::fromStdString(list).replace(u';', u' ');
    }();
    return filter;
}

}  // namespace io
