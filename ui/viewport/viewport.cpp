#include "viewport.h"

#include "strain_legend.h"

#include <QFile>
#include <QKeyEvent>
#include <QLineF>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLBuffer>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QRegularExpression>
#include <QVector2D>
#include <QWheelEvent>
#include <QtDebug>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ui {

namespace {

constexpr float kWheelZoomPerNotch = 0.85f;  // distance factor for one wheel notch towards the scene
constexpr int kPositionLocation = 1;        // the per-particle attributes, as the shaders declare them
constexpr int kRadiusLocation = 2;
constexpr int kColourLocation = 3;
constexpr int kMarksLocation = 4;
constexpr int kOrientationLocation = 5;  // only while the balls turn (Gpu::turning)
constexpr int kSurfacePositionLocation = 0;  // the sheet's attributes (surface.vert)
constexpr int kSurfaceNormalLocation = 1;
// the corners of a line's quad as line.vert takes them: (end, side)
constexpr float kLineCorners[] = {0.0f, -1.0f, 0.0f, 1.0f, 1.0f, -1.0f, 1.0f, 1.0f};

// a shader from the resources, with its #include "file" lines replaced by that file
QByteArray shaderSource(const QString &name)
{
    QFile file(QStringLiteral(":/shaders/") + name);
    if (!file.open(QIODevice::ReadOnly)) {
        qWarning("viewport: cannot read shader %s", qPrintable(file.fileName()));
        return {};
    }
    QString text = QString::fromUtf8(file.readAll());
    static const QRegularExpression include(QStringLiteral("^#include \"([^\"]+)\"$"),
                                            QRegularExpression::MultilineOption);
    for (QRegularExpressionMatch match = include.match(text); match.hasMatch(); match = include.match(text))
        text.replace(match.capturedStart(), match.capturedLength(), QString::fromUtf8(shaderSource(match.captured(1))));
    return text.toUtf8();
}

bool buildProgram(QOpenGLShaderProgram &program, const QString &vertex, const QString &fragment)
{
    const bool ok = program.addShaderFromSourceCode(QOpenGLShader::Vertex, shaderSource(vertex)) &&
                    program.addShaderFromSourceCode(QOpenGLShader::Fragment, shaderSource(fragment)) && program.link();
    if (!ok)
        qWarning("viewport: shaders %s + %s: %s", qPrintable(vertex), qPrintable(fragment), qPrintable(program.log()));
    return ok;
}

}  // namespace

// everything that lives in the GL context; destroyed with the context current
struct Viewport::Gpu {
    QOpenGLShaderProgram impostorProgram;
    QOpenGLShaderProgram meshProgram;
    QOpenGLShaderProgram flatProgram;
    QOpenGLShaderProgram lineProgram;
    QOpenGLShaderProgram surfaceProgram;

    // per-vertex geometry of one particle
    QOpenGLBuffer quad{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer sphere{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer sphereIndices{QOpenGLBuffer::IndexBuffer};
    int sphereIndexCount = 0;

    // per-particle data: positions streamed, style uploaded when it changes
    QOpenGLBuffer positions{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer styles{QOpenGLBuffer::VertexBuffer};
    int positionCount = 0;  // particles in `positions`, which the sheet's corners index
    int particleCount = 0;  // instances with a position
    int styleCount = 0;     // instances with a style
    // the positions of the particles drawn, where a sheet hides the others (styles then holds
    // theirs alone); the particles' VAOs read their positions from here while `compacted`
    QOpenGLBuffer drawnPositions{QOpenGLBuffer::VertexBuffer};
    bool compacted = false;
    // the drawn particles' orientations, while the scene turns (the particles' VAOs read them then)
    QOpenGLBuffer orientations{QOpenGLBuffer::VertexBuffer};
    bool turning = false;
    // one identity quaternion, which every instance reads while nothing turns
    QOpenGLBuffer unturned{QOpenGLBuffer::VertexBuffer};

    // lines, a pair of vertices each, drawn as instances of the line program's quad
    QOpenGLBuffer lineCorners{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer springs{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer decorations{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer arrow{QOpenGLBuffer::VertexBuffer};  // the steering arrow, packed each frame
    int springLines = 0;
    int highlightedSprings = 0;  // the last of them, drawn wider
    int decorationLines = 0;

    // triangles for the flat program
    QOpenGLBuffer planes{QOpenGLBuffer::VertexBuffer};
    int planeVertices = 0;

    // the sheet: the particles' positions, their normals and the triangles' corners
    QOpenGLBuffer normals{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer surfaceIndices{QOpenGLBuffer::IndexBuffer};
    int surfaceIndexCount = 0;

    QOpenGLVertexArrayObject impostorVao;
    QOpenGLVertexArrayObject meshVao;
    QOpenGLVertexArrayObject springsVao;
    QOpenGLVertexArrayObject decorationsVao;
    QOpenGLVertexArrayObject arrowVao;
    QOpenGLVertexArrayObject planesVao;
    QOpenGLVertexArrayObject surfaceVao;
};

Viewport::Viewport(QWidget *parent) : QOpenGLWidget(parent)
{
    QSurfaceFormat format = requestedFormat();
    if (drawnOnTheCpu())
        format.setSamples(0);
    setFormat(format);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    m_camera.setViewportSize(size());
    m_legend = new StrainLegend(this);
    m_legend->hide();

    // the frame time runs from the start of paintGL to the frame reaching the screen
    connect(this, &QOpenGLWidget::frameSwapped, this, [this] {
        if (m_frameTiming) {
            m_frameTiming = false;
            emit frameTimeMeasured(double(m_frameClock.nsecsElapsed()) * 1.0e-9);
        }
    });
}

Viewport::~Viewport()
{
    // free now, and stop the context (destroyed by ~QOpenGLWidget) from calling back into a
    // Viewport that is no longer there
    cleanupGL();
    if (QOpenGLContext *glContext = context())
        disconnect(glContext, &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanupGL);
}

QSurfaceFormat Viewport::requestedFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    return format;
}

void Viewport::pointOrientations(QOpenGLBuffer &buffer, bool perInstance)
{
    buffer.bind();
    glEnableVertexAttribArray(kOrientationLocation);
    glVertexAttribPointer(kOrientationLocation, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    // (a divisor past any instance count: every instance reads the first)
    glVertexAttribDivisor(kOrientationLocation, perInstance ? 1 : 0x40000000);
}

void Viewport::setSnapshot(std::shared_ptr<const core::Snapshot> snapshot)
{
    // a frame that answers a message with the snapshot already shown (a Pause): nothing to draw
    // again, which on a software renderer at 10⁶ particles would hold the window for seconds
    if (snapshot == m_snapshot)
        return;
    m_snapshot = std::move(snapshot);
    m_positionsStale = true;
    refreshSurface();
    followSelection();
    if (!m_framed && m_snapshot && m_snapshot->particleCount() > 0) {
        frameAll();
        m_autoFramed = true;
    }
    update();
}

void Viewport::setPlanes(const std::vector<core::PlaneDesc> &planes)
{
    m_planes = planes;
    m_decorationsChanged = true;
    update();
}

void Viewport::setSteeringArrow(const SteeringArrow &arrow)
{
    if (arrow == m_steeringArrow)
        return;
    m_steeringArrow = arrow;
    update();
}

void Viewport::setSelection(const std::vector<int> &particles)
{
    m_selection = particles;
    m_selectionChanged = true;
    followSelection();
    update();
}

void Viewport::setSpringSelection(const std::vector<int> &springs)
{
    m_springHighlight.selected = springs;
    m_positionsStale = true;  // the spring lines carry the colours
    update();
}

void Viewport::setHover(int particle, int spring)
{
    if (particle == m_hoverParticle && spring == m_springHighlight.hover)
        return;
    m_hoverParticle = particle;
    m_springHighlight.hover = spring;
    m_selectionChanged = true;
    m_positionsStale = true;
    update();
}

void Viewport::setLayers(const ViewLayers &layers)
{
    if (layers == m_layers)
        return;
    m_layers = layers;
    m_surfaceKey.clear();
    refreshSurface();
    update();
}

void Viewport::refreshSurface()
{
    if (!m_snapshot) {
        m_legend->hide();
        return;
    }
    const core::Snapshot &s = *m_snapshot;
    if (m_surfaceKey.matches(s))
        return;
    m_surface = packSurface(s);
    m_surfaceKey.remember(s);
    m_surfaceChanged = true;
    m_selectionChanged = true;  // the particles' style hides the sheet's spheres
    m_positionsStale = true;    // and the spring lines its springs

    // what the sheet hides: its spheres and springs, unless the layers show them too
    const bool sheet = m_layers.surface && m_surface.triangleCount() > 0;
    m_hiddenParticles.clear();
    m_hiddenSprings.clear();
    if (sheet && !m_layers.surfaceSpheres)
        m_hiddenParticles = m_surface.coveredParticles;
    if (sheet && !m_layers.surfaceSprings)
        m_hiddenSprings = m_surface.coveredSprings;

    // the legend while any spring is drawn in its strain's colour
    bool anySpring = false;
    for (int k = 0; k < s.springCount() && !anySpring; ++k)
        anySpring = !s.isBroken(k) && (k >= int(m_hiddenSprings.size()) || m_hiddenSprings[std::size_t(k)] == 0);
    m_legend->setVisible(anySpring);
}

void Viewport::setParticleDrawing(ParticleDrawing drawing)
{
    m_drawing = drawing;
    update();
}

void Viewport::frameAll()
{
    const Sphere bounds = particleExtent();
    updateSceneBounds(bounds);
    m_camera.setViewportSize(size());
    const Sphere framed = withEnclosedFloors(m_planes, bounds);
    m_camera.frameSphere(framed.centre, framed.radius);
    m_framed = true;
    m_autoFramed = false;
    update();
}

void Viewport::updateSceneBounds(const Sphere &bounds)
{
    m_sceneBounds = bounds;
    m_camera.setSceneBounds(bounds.centre, bounds.radius);
    m_decorationsChanged = true;
}

int Viewport::particleAt(const QPointF &pixel) const
{
    if (!m_snapshot)
        return -1;
    const core::Snapshot &s = *m_snapshot;
    const int n = std::min<int>(s.particleCount(), int(s.positions.size() / 3));
    const Ray ray = m_camera.unproject(pixel);

    // the nearest sphere in front of the eye that the ray passes through
    int nearest = -1;
    float nearestDistance = std::numeric_limits<float>::infinity();
    for (int i = 0; i < n; ++i) {
        const QVector3D centre(s.positions[3 * i], s.positions[3 * i + 1], s.positions[3 * i + 2]);
        const QVector3D toCentre = centre - ray.origin;
        const float along = QVector3D::dotProduct(toCentre, ray.direction);
        const float missSquared = (toCentre - along * ray.direction).lengthSquared();
        const float r = s.radii[i];
        if (missSquared > r * r)
            continue;
        const float distance = along - std::sqrt(r * r - missSquared);
        if (distance > 0.0f && distance < nearestDistance) {
            nearest = i;
            nearestDistance = distance;
        }
    }
    if (nearest >= 0)
        return nearest;

    // else the centre nearest the pixel on screen, if near enough
    float best = kPickPixels;
    for (int i = 0; i < n; ++i) {
        const auto onScreen =
            m_camera.project(QVector3D(s.positions[3 * i], s.positions[3 * i + 1], s.positions[3 * i + 2]));
        if (!onScreen)
            continue;
        const float d = float(QLineF(*onScreen, pixel).length());
        if (d <= best) {
            best = d;
            nearest = i;
        }
    }
    return nearest;
}

int Viewport::springAt(const QPointF &pixel) const
{
    if (!m_snapshot)
        return -1;
    const core::Snapshot &s = *m_snapshot;
    const int springs = std::min<int>(s.springCount(), int(s.springEnds.size() / 6));
    int nearest = -1;
    float best = kPickPixels;
    for (int k = 0; k < springs; ++k) {
        if (s.isBroken(k) || (k < int(m_hiddenSprings.size()) && m_hiddenSprings[std::size_t(k)] != 0))
            continue;  // not drawn, so not picked
        const float *e = s.springEnds.data() + std::size_t(k) * 6;
        const auto a = m_camera.project(QVector3D(e[0], e[1], e[2]));
        const auto b = m_camera.project(QVector3D(e[3], e[4], e[5]));
        if (!a || !b)
            continue;
        // distance from the pixel to the segment a-b on screen
        const QPointF ab = *b - *a;
        const double lengthSquared = QPointF::dotProduct(ab, ab);
        const double t = lengthSquared > 0.0 ? std::clamp(QPointF::dotProduct(pixel - *a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
        const float d = float(QLineF(*a + t * ab, pixel).length());
        if (d <= best) {
            best = d;
            nearest = k;
        }
    }
    return nearest;
}

bool Viewport::drawnOnTheCpu()
{
    static const bool software = [] {
        QOpenGLContext context;
        context.setFormat(requestedFormat());
        QOffscreenSurface surface;
        surface.setFormat(context.format());
        surface.create();
        if (!context.create() || !context.makeCurrent(&surface))
            return false;
        const auto *name = reinterpret_cast<const char *>(context.functions()->glGetString(GL_RENDERER));
        const QByteArray renderer = QByteArray(name ? name : "").toLower();
        context.doneCurrent();
        return renderer.contains("llvmpipe") || renderer.contains("softpipe") || renderer.contains("swrast");
    }();
    return software;
}

void Viewport::initializeGL()
{
    if (!initializeOpenGLFunctions()) {
        qWarning("viewport: OpenGL 3.3 core is not available; nothing will be drawn");
        return;
    }

    // the context can go away before the widget does (e.g. when it moves to another window)
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::cleanupGL);

    // what the driver really gave us, once per run
    static bool logged = false;
    if (!logged) {
        logged = true;
        qInfo("viewport: OpenGL %s, %s", reinterpret_cast<const char *>(glGetString(GL_VERSION)),
              reinterpret_cast<const char *>(glGetString(GL_RENDERER)));
    }

    // the largest image renderImage() can make: a renderbuffer, a texture and a viewport that big
    GLint renderbuffer = 0, texture = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    m_maxImageSide = std::min({renderbuffer, texture, viewport[0], viewport[1]});
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    m_exportSamples = std::clamp(requestedFormat().samples(), 0, int(maxSamples));

    // the three programs: impostor spheres, mesh spheres, flat lines and triangles
    auto gpu = std::make_unique<Gpu>();
    const bool built =
        buildProgram(gpu->impostorProgram, QStringLiteral("particle_impostor.vert"),
                     QStringLiteral("particle_impostor.frag")) &&
        buildProgram(gpu->meshProgram, QStringLiteral("particle_mesh.vert"), QStringLiteral("particle_mesh.frag")) &&
        buildProgram(gpu->flatProgram, QStringLiteral("flat.vert"), QStringLiteral("flat.frag")) &&
        buildProgram(gpu->lineProgram, QStringLiteral("line.vert"), QStringLiteral("flat.frag")) &&
        buildProgram(gpu->surfaceProgram, QStringLiteral("surface.vert"), QStringLiteral("surface.frag"));
    if (!built)
        return;

    // static geometry: the impostor's quad and the mesh sphere
    const float corners[] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
    gpu->quad.create();
    gpu->quad.bind();
    gpu->quad.allocate(corners, int(sizeof(corners)));
    const SphereMesh sphere = icosphere(kSphereMeshSubdivisions);
    gpu->sphere.create();
    gpu->sphere.bind();
    gpu->sphere.allocate(sphere.vertices.data(), int(sphere.vertices.size() * sizeof(float)));
    gpu->sphereIndexCount = int(sphere.indices.size());
    gpu->lineCorners.create();
    gpu->lineCorners.bind();
    gpu->lineCorners.allocate(kLineCorners, int(sizeof(kLineCorners)));

    const float identity[] = {1.0f, 0.0f, 0.0f, 0.0f};
    gpu->unturned.create();
    gpu->unturned.bind();
    gpu->unturned.allocate(identity, int(sizeof(identity)));

    // dynamic buffers, empty for now
    for (QOpenGLBuffer *buffer :
         {&gpu->positions, &gpu->drawnPositions, &gpu->orientations, &gpu->springs, &gpu->normals, &gpu->arrow}) {
        buffer->setUsagePattern(QOpenGLBuffer::StreamDraw);
        buffer->create();
    }
    for (QOpenGLBuffer *buffer : {&gpu->styles, &gpu->decorations, &gpu->planes}) {
        buffer->setUsagePattern(QOpenGLBuffer::StaticDraw);
        buffer->create();
    }

    // the per-particle attributes, shared by both particle drawings
    auto bindParticleAttributes = [this, &gpu] {
        gpu->positions.bind();
        glEnableVertexAttribArray(kPositionLocation);
        glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glVertexAttribDivisor(kPositionLocation, 1);
        gpu->styles.bind();
        const struct {
            int location, size, offset;
        } styleAttributes[] = {{kRadiusLocation, 1, 0}, {kColourLocation, 3, 1}, {kMarksLocation, 2, 4}};
        for (const auto &a : styleAttributes) {
            glEnableVertexAttribArray(a.location);
            glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, kStyleFloats * sizeof(float),
                                  reinterpret_cast<const void *>(std::uintptr_t(a.offset * sizeof(float))));
            glVertexAttribDivisor(a.location, 1);
        }
        pointOrientations(gpu->unturned, false);
    };

    // impostors: a 2D corner per vertex
    gpu->impostorVao.create();
    gpu->impostorVao.bind();
    gpu->quad.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    bindParticleAttributes();

    // meshes: a point of the unit sphere per vertex, and the index buffer
    gpu->meshVao.create();
    gpu->meshVao.bind();
    gpu->sphere.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gpu->sphereIndices.create();
    gpu->sphereIndices.bind();
    gpu->sphereIndices.allocate(sphere.indices.data(), int(sphere.indices.size() * sizeof(std::uint32_t)));
    bindParticleAttributes();

    // flat triangles: position and colour per vertex
    gpu->planesVao.create();
    gpu->planesVao.bind();
    gpu->planes.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kVertexFloats * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kVertexFloats * sizeof(float),
                          reinterpret_cast<const void *>(3 * sizeof(float)));

    // lines: the quad's corner per vertex; per line its pair of vertices, read as end a, its
    // colour and end b
    for (auto [vao, buffer] : {std::pair{&gpu->springsVao, &gpu->springs},
                               std::pair{&gpu->decorationsVao, &gpu->decorations}, std::pair{&gpu->arrowVao, &gpu->arrow}}) {
        vao->create();
        vao->bind();
        gpu->lineCorners.bind();
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
        buffer->bind();
        const struct {
            int location, size, offset;
        } lineAttributes[] = {{1, 3, 0}, {2, 4, 3}, {3, 3, kVertexFloats}};
        for (const auto &a : lineAttributes) {
            glEnableVertexAttribArray(a.location);
            glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, 2 * kVertexFloats * sizeof(float),
                                  reinterpret_cast<const void *>(std::uintptr_t(a.offset * sizeof(float))));
            glVertexAttribDivisor(a.location, 1);
        }
    }

    // the sheet: position and normal per particle, and the corners' indices
    gpu->surfaceVao.create();
    gpu->surfaceVao.bind();
    gpu->positions.bind();
    glEnableVertexAttribArray(kSurfacePositionLocation);
    glVertexAttribPointer(kSurfacePositionLocation, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gpu->normals.bind();
    glEnableVertexAttribArray(kSurfaceNormalLocation);
    glVertexAttribPointer(kSurfaceNormalLocation, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gpu->surfaceIndices.setUsagePattern(QOpenGLBuffer::StaticDraw);
    gpu->surfaceIndices.create();
    gpu->surfaceIndices.bind();
    gpu->surfaceVao.release();

    // everything is to be uploaded again into the new buffers
    m_gpu = std::move(gpu);
    m_positionsStale = true;
    m_styleKey.clear();
    m_decorationsChanged = true;
    m_surfaceChanged = true;
    m_samples = -1;
}

void Viewport::cleanupGL()
{
    // hellogl2's way: make the context current, free, release
    if (!m_gpu)
        return;
    makeCurrent();
    m_gpu.reset();
    doneCurrent();
}

void Viewport::resizeGL(int, int)
{
    // the first framing was made for whatever size the widget had before it was laid out
    m_camera.setViewportSize(size());
    if (m_autoFramed) {
        frameAll();
        m_autoFramed = true;
    }
}

void Viewport::uploadSnapshot()
{
    Gpu &gpu = *m_gpu;
    if (!m_snapshot) {
        gpu.positionCount = 0;
        gpu.particleCount = 0;
        gpu.styleCount = 0;
        gpu.springLines = 0;
        gpu.surfaceIndexCount = 0;
        return;
    }
    const core::Snapshot &s = *m_snapshot;

    // the style, only when the radii, the pins or the selection changed; of the particles drawn
    // alone where a sheet hides some
    bool regather = false;
    if (m_selectionChanged || !m_styleKey.matches(s)) {
        const ParticleStyle style = packParticleStyle(s, m_selection, m_hoverParticle, m_hiddenParticles);
        m_drawn = drawnParticles(style);
        gpu.styles.bind();
        if (m_drawn.all) {
            gpu.styles.allocate(style.values.data(), int(style.values.size() * sizeof(float)));
            gpu.styleCount = style.count();
        } else {
            gatherRows(style.values.data(), kStyleFloats, m_drawn.rows, m_gathered);
            gpu.styles.allocate(m_gathered.data(), int(m_gathered.size() * sizeof(float)));
            gpu.styleCount = int(m_drawn.rows.size());
        }
        m_styleKey.remember(s);
        m_selectionChanged = false;
        ++m_styleUploads;
        regather = true;
    }

    // positions and spring lines, once per new snapshot
    if (m_positionsStale) {
        gpu.positions.bind();
        if (m_surface.extraVertices > 0 && m_layers.surface) {
            // the soft bodies' surface vertices after the particles, in the buffer both read
            surfacePositions(s, m_surface, m_surfacePositions);
            gpu.positions.allocate(m_surfacePositions.data(), int(m_surfacePositions.size() * sizeof(float)));
        } else {
            gpu.positions.allocate(s.positions.data(), int(s.positions.size() * sizeof(float)));
        }
        gpu.highlightedSprings = packSpringLines(s, m_springVertices, kFullStrain, m_springHighlight, m_hiddenSprings);
        gpu.springs.bind();
        gpu.springs.allocate(m_springVertices.data(), int(m_springVertices.size() * sizeof(float)));
        gpu.springLines = int(m_springVertices.size() / (2 * kVertexFloats));
        regather = true;
        // the sheet's normals at these positions
        if (m_surface.triangleCount() > 0 && m_layers.surface) {
            if (m_surface.extraVertices == 0)
                surfaceNormals(s.positions, m_surface.indices, m_normals);
            else
                surfaceNormals(m_surfacePositions, m_surface.indices, m_normals);
            gpu.normals.bind();
            gpu.normals.allocate(m_normals.data(), int(m_normals.size() * sizeof(float)));
        }
        m_positionsStale = false;
    }

    // the drawn particles' positions, from the buffer the sheet reads when all are drawn
    if (regather) {
        const int n = std::min<int>(s.particleCount(), int(s.positions.size() / 3));
        gpu.positionCount = n;
        if (m_drawn.all) {
            gpu.particleCount = n;
        } else {
            const auto end = std::lower_bound(m_drawn.rows.begin(), m_drawn.rows.end(), std::uint32_t(n));
            m_drawn.rows.erase(end, m_drawn.rows.end());
            gatherRows(s.positions.data(), 3, m_drawn.rows, m_gathered);
            gpu.drawnPositions.bind();
            gpu.drawnPositions.allocate(m_gathered.data(), int(m_gathered.size() * sizeof(float)));
            gpu.particleCount = int(m_drawn.rows.size());
        }
        // the orientations of the same particles, where the scene turns
        const bool turning = n > 0 && s.orientations.size() == 4 * std::size_t(n);
        if (turning) {
            gpu.orientations.bind();
            if (m_drawn.all) {
                gpu.orientations.allocate(s.orientations.data(), int(4 * n * sizeof(float)));
            } else {
                gatherRows(s.orientations.data(), 4, m_drawn.rows, m_gathered);
                gpu.orientations.allocate(m_gathered.data(), int(m_gathered.size() * sizeof(float)));
            }
        }
        if (gpu.turning != turning) {
            gpu.turning = turning;
            for (QOpenGLVertexArrayObject *vao : {&gpu.impostorVao, &gpu.meshVao}) {
                vao->bind();
                pointOrientations(turning ? gpu.orientations : gpu.unturned, turning);
                vao->release();
            }
        }
        if (gpu.compacted != !m_drawn.all) {
            gpu.compacted = !m_drawn.all;
            QOpenGLBuffer &source = gpu.compacted ? gpu.drawnPositions : gpu.positions;
            for (QOpenGLVertexArrayObject *vao : {&gpu.impostorVao, &gpu.meshVao}) {
                vao->bind();
                source.bind();
                glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
                vao->release();
            }
        }
    }

    // the sheet's triangles, when they or the broken springs changed
    if (m_surfaceChanged) {
        gpu.surfaceVao.bind();
        gpu.surfaceIndices.bind();
        gpu.surfaceIndices.allocate(m_surface.indices.data(), int(m_surface.indices.size() * sizeof(std::uint32_t)));
        gpu.surfaceVao.release();
        gpu.surfaceIndexCount = int(m_surface.indices.size());
        m_surfaceChanged = false;
    }
}

void Viewport::uploadDecorations()
{
    if (!m_decorationsChanged)
        return;
    Gpu &gpu = *m_gpu;

    // the grid on the floors, none in a scene without one
    std::vector<float> lines = packFloorGrids(m_planes, m_sceneBounds);
    const std::vector<float> axes = packAxes(2.0f * niceStep(m_sceneBounds.radius / 4.0f));
    lines.insert(lines.end(), axes.begin(), axes.end());
    gpu.decorations.bind();
    gpu.decorations.allocate(lines.data(), int(lines.size() * sizeof(float)));
    gpu.decorationLines = int(lines.size() / (2 * kVertexFloats));

    const std::vector<float> quads = packPlaneQuads(m_planes, m_sceneBounds);
    gpu.planes.bind();
    gpu.planes.allocate(quads.data(), int(quads.size() * sizeof(float)));
    gpu.planeVertices = int(quads.size() / kVertexFloats);
    m_decorationsChanged = false;
}

void Viewport::paintGL()
{
    m_frameClock.start();
    m_frameTiming = true;
    if (m_gpu && m_samples < 0)
        glGetIntegerv(GL_SAMPLES, &m_samples);
    // the framebuffer's size in device pixels, as QOpenGLWidget set the viewport to it
    GLint viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, viewport);
    drawScene(m_camera, m_samples, QSize(viewport[2], viewport[3]));
}

QImage Viewport::renderImage(QSize size, QString *error)
{
    auto fail = [error](const QString &reason) {
        if (error)
            *error = reason;
        return QImage();
    };
    if (size.width() < 1 || size.height() < 1)
        return fail(tr("%1 × %2 px is not an image size: both must be at least 1")
                        .arg(size.width())
                        .arg(size.height()));
    if (!m_gpu || !isValid())
        return fail(tr("the 3D view has no OpenGL context yet, so nothing can be drawn"));
    if (size.width() > m_maxImageSide || size.height() > m_maxImageSide)
        return fail(tr("%1 × %2 px is larger than this OpenGL driver can draw: at most %3 px a side")
                        .arg(size.width())
                        .arg(size.height())
                        .arg(m_maxImageSide));

    // a framebuffer of the requested size, with depth and the multisampling the view asks for (the
    // widget's format() is its context's, which has no samples: its own framebuffer has them)
    makeCurrent();
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setSamples(m_exportSamples);
    QImage image;
    {
        QOpenGLFramebufferObject framebuffer(size, format);
        if (framebuffer.isValid() && framebuffer.bind()) {
            // the same camera, with the aspect ratio of the image
            Camera camera = m_camera;
            camera.setViewportSize(size);
            glViewport(0, 0, size.width(), size.height());
            drawScene(camera, framebuffer.format().samples(), size);
            // the stored alpha made opaque: the outlines' coverage can leave it under one (the
            // driver need not honour alpha-to-one), and the image, read as premultiplied, would
            // then be divided by it into bright rims. The view on screen ignores alpha already.
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            framebuffer.release();
            image = framebuffer.toImage().convertToFormat(QImage::Format_RGB32);
        }
    }
    doneCurrent();
    if (image.isNull())
        return fail(tr("OpenGL could not make a %1 × %2 px framebuffer (out of memory?)")
                        .arg(size.width())
                        .arg(size.height()));
    return image;
}

double Viewport::lineScale(int framebufferHeight) const
{
    return height() > 0 && framebufferHeight > 0 ? double(framebufferHeight) / height() : 1.0;
}

void Viewport::drawScene(const Camera &camera, int samples, QSize pixels)
{
    glClearColor(kBackgroundColour[0], kBackgroundColour[1], kBackgroundColour[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_gpu)
        return;
    Gpu &gpu = *m_gpu;

    uploadSnapshot();
    uploadDecorations();

    const QMatrix4x4 view = camera.viewMatrix();
    const QMatrix4x4 projection = camera.projectionMatrix();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    // lines: grid and axes, then springs (the highlighted ones last and wider), as many pixels
    // wide in the framebuffer as the view's are scaled to it, and never under one
    const float scale = float(lineScale(pixels.height()));
    auto widthOf = [scale](float viewPixels) { return std::max(viewPixels * scale, 1.0f); };
    gpu.lineProgram.bind();
    gpu.lineProgram.setUniformValue("viewProjection", projection * view);
    gpu.lineProgram.setUniformValue("pixels", QVector2D(float(pixels.width()), float(pixels.height())));
    if (gpu.decorationLines > 0) {
        gpu.lineProgram.setUniformValue("width", widthOf(kDecorationPixels));
        gpu.lineProgram.setUniformValue("wideFrom", gpu.decorationLines);
        gpu.decorationsVao.bind();
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, gpu.decorationLines);
    }
    if (gpu.springLines > 0) {
        gpu.lineProgram.setUniformValue("width", widthOf(kSpringPixels));
        gpu.lineProgram.setUniformValue("wideWidth", widthOf(kHighlightedSpringPixels));
        gpu.lineProgram.setUniformValue("wideFrom", gpu.springLines - gpu.highlightedSprings);
        gpu.springsVao.bind();
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, gpu.springLines);
    }

    // the sheet, both sides, a little behind the lines that lie in it
    if (m_layers.surface && gpu.surfaceIndexCount > 0 && gpu.positionCount > 0) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        gpu.surfaceProgram.bind();
        gpu.surfaceProgram.setUniformValue("view", view);
        gpu.surfaceProgram.setUniformValue("projection", projection);
        auto toVector3 = [](const Rgb &c) { return QVector3D(c[0], c[1], c[2]); };
        gpu.surfaceProgram.setUniformValue("frontColour", toVector3(kSurfaceFrontColour));
        gpu.surfaceProgram.setUniformValue("backColour", toVector3(kSurfaceBackColour));
        gpu.surfaceVao.bind();
        glDrawElements(GL_TRIANGLES, gpu.surfaceIndexCount, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_POLYGON_OFFSET_FILL);
    }

    // particles, one instance each
    const int particles = std::min(gpu.particleCount, gpu.styleCount);
    if (particles > 0 && m_drawing == ParticleDrawing::Impostor) {
        // outlines smoothed by alpha to coverage, with the stored alpha kept at one
        const bool smooth = samples > 0;
        if (smooth) {
            glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
        }
        gpu.impostorProgram.bind();
        gpu.impostorProgram.setUniformValue("view", view);
        gpu.impostorProgram.setUniformValue("projection", projection);
        gpu.impostorProgram.setUniformValue("smoothEdges", smooth);
        gpu.impostorProgram.setUniformValue("patterned", gpu.turning);
        gpu.impostorVao.bind();
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, particles);
        glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    } else if (particles > 0) {
        glEnable(GL_CULL_FACE);
        gpu.meshProgram.bind();
        gpu.meshProgram.setUniformValue("view", view);
        gpu.meshProgram.setUniformValue("projection", projection);
        gpu.meshProgram.setUniformValue("patterned", gpu.turning);
        gpu.meshVao.bind();
        glDrawElementsInstanced(GL_TRIANGLES, gpu.sphereIndexCount, GL_UNSIGNED_INT, nullptr, particles);
        glDisable(GL_CULL_FACE);
    }

    // translucent planes last, over everything, leaving depth and the stored alpha alone
    if (gpu.planeVertices > 0) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glDepthMask(GL_FALSE);
        gpu.flatProgram.bind();
        gpu.flatProgram.setUniformValue("viewProjection", projection * view);
        gpu.planesVao.bind();
        glDrawArrays(GL_TRIANGLES, 0, gpu.planeVertices);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    // the steering arrow over everything, the ball it starts in included
    if (m_snapshot && m_steeringArrow.visible()) {
        const std::vector<float> arrow = packSteeringArrow(m_steeringArrow, *m_snapshot, camera.eye());
        if (!arrow.empty()) {
            glDisable(GL_DEPTH_TEST);
            gpu.arrow.bind();
            gpu.arrow.allocate(arrow.data(), int(arrow.size() * sizeof(float)));
            gpu.lineProgram.bind();
            gpu.lineProgram.setUniformValue("width", widthOf(kSteeringArrowPixels));
            gpu.lineProgram.setUniformValue("wideFrom", int(arrow.size() / (2 * kVertexFloats)));
            gpu.arrowVao.bind();
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, int(arrow.size() / (2 * kVertexFloats)));
            glEnable(GL_DEPTH_TEST);
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

void Viewport::mousePressEvent(QMouseEvent *event)
{
    // middle or shift+left pans; right orbits, and so does left unless it lands on a particle (the
    // editing tools filter the left button first and take what they need)
    m_lastMouse = event->position();
    const bool left = event->button() == Qt::LeftButton;
    if (event->button() == Qt::MiddleButton || (left && event->modifiers().testFlag(Qt::ShiftModifier))) {
        m_drag = Drag::Pan;
    } else if (event->button() == Qt::RightButton) {
        m_drag = Drag::Orbit;
    } else if (left) {
        const int particle = particleAt(event->position());
        m_drag = particle < 0 ? Drag::Orbit : Drag::None;
        if (particle >= 0)
            emit particlePressed(particle, event->modifiers());
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    if (m_drag != Drag::None) {
        m_autoFramed = false;
        setCursor(m_drag == Drag::Pan ? Qt::SizeAllCursor : Qt::ClosedHandCursor);
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPointF delta = event->position() - m_lastMouse;
    m_lastMouse = event->position();
    if (m_drag == Drag::Orbit)
        m_camera.orbit(float(delta.x()), float(delta.y()));
    else
        m_camera.pan(float(delta.x()), float(delta.y()));
    event->accept();
    update();
}

void Viewport::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    m_drag = Drag::None;
    unsetCursor();
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent *event)
{
    // one notch (120 eighths of a degree) scales the distance by a fixed factor, about the cursor
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        QOpenGLWidget::wheelEvent(event);
        return;
    }
    m_camera.zoomAt(event->position(), float(std::pow(double(kWheelZoomPerNotch), notches)));
    m_autoFramed = false;
    event->accept();
    update();
}

void Viewport::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_F || event->key() == Qt::Key_Home) {
        frameAll();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

}  // namespace ui
