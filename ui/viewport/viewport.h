#pragma once
// Viewport: the 3D view of the simulation (OpenGL 3.3 core). It draws the latest Snapshot it was
// given and never waits for a step: particles as instanced spheres (ray-cast impostor quads by
// default, a mesh as the alternative — bench/viewport_fps.cpp compares them), springs as lines
// coloured by strain (instanced quads a few pixels wide, with a legend in the corner), the
// triangles of a spring mesh (a cloth) as a shaded two-sided sheet that torn springs open, planes
// as translucent squares around the scene, a ground grid on the floors (planes facing up), the
// axes, and the steering arrow over all (steering_arrow.h). The particles and springs
// the sheet already shows are hidden unless the layers ask for them (or they are selected).
// Positions are streamed once per new snapshot; radii, colours and marks are uploaded only when the
// particles' radii or pins, or the selection, change. GL resources are made in initializeGL and
// freed when the context goes away, as Qt's hellogl2 example does. renderImage() draws the same
// scene (one drawing function for both) into an offscreen framebuffer of any size, for exports.
// The camera's views (the presets, the projection, following the selection) are viewport_camera.cpp.

#include "camera.h"
#include "render_data.h"
#include "steering_arrow.h"
#include "surface_data.h"

#include "core/model/scene.h"
#include "core/model/snapshot.h"

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLBuffer>
#include <QOpenGLWidget>
#include <QPoint>

#include <memory>
#include <vector>

namespace ui {

class StrainLegend;

// the mesh drawing's sphere: an icosahedron split this many times (80 triangles)
inline constexpr int kSphereMeshSubdivisions = 1;

// what is drawn of a scene whose springs make triangles (the View menu's toggles)
struct ViewLayers {
    bool surface = true;          // the triangles as a sheet
    bool surfaceSpheres = false;  // and the spheres of the particles at its corners
    bool surfaceSprings = false;  // and the springs that lie in it

    bool operator==(const ViewLayers &) const = default;
};

enum class ParticleDrawing {
    Impostor,  // a camera-facing quad per particle, the sphere found per fragment (the default)
    Mesh,      // an instanced icosphere
};

class Viewport : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT

public:
    explicit Viewport(QWidget *parent = nullptr);
    ~Viewport() override;

    // the surface format the viewport asks for: OpenGL 3.3 core, depth, 4× MSAA; main() should
    // make it the default before the QApplication exists (with Qt::AA_ShareOpenGLContexts)
    static QSurfaceFormat requestedFormat();
    // whether OpenGL is drawn on the CPU here (Mesa's llvmpipe, softpipe or swrast), asked once of
    // a throwaway context (needs the QGuiApplication). There the view is not multisampled: 4×
    // multisampling doubles a frame's cost (34 against 81 ms for a 200 × 200 cloth on llvmpipe),
    // and every frame is time the run and the answer to a key wait for. Exported images keep it.
    static bool drawnOnTheCpu();

    // the frame to draw; the first one with particles also frames the view (and frames it again
    // when the widget is resized, until the view is moved)
    void setSnapshot(std::shared_ptr<const core::Snapshot> snapshot);
    std::shared_ptr<const core::Snapshot> snapshot() const { return m_snapshot; }

    // the scene's planes, drawn as translucent squares around the particles
    void setPlanes(const std::vector<core::PlaneDesc> &planes);

    // the steering push, drawn as an arrow at the steered particle over everything (hidden
    // when the arrow is: no push, or nothing to steer)
    void setSteeringArrow(const SteeringArrow &arrow);
    const SteeringArrow &steeringArrow() const { return m_steeringArrow; }

    // indices of the highlighted particles and springs
    void setSelection(const std::vector<int> &particles);
    const std::vector<int> &selection() const { return m_selection; }
    void setSpringSelection(const std::vector<int> &springs);
    // what a click would pick, drawn in the hover colour; -1 for none
    void setHover(int particle, int spring);
    int hoveredParticle() const { return m_hoverParticle; }
    int hoveredSpring() const { return m_springHighlight.hover; }

    void setLayers(const ViewLayers &layers);
    const ViewLayers &layers() const { return m_layers; }
    // the triangles drawn as the sheet now (none while the surface layer is off)
    int surfaceTriangles() const { return m_layers.surface ? m_surface.triangleCount() : 0; }
    // the key to the springs' colours, shown while springs are drawn
    const StrainLegend *strainLegend() const { return m_legend; }

    void setParticleDrawing(ParticleDrawing drawing);
    ParticleDrawing particleDrawing() const { return m_drawing; }

    Camera &camera() { return m_camera; }
    const Camera &camera() const { return m_camera; }

    // the View menu's camera (viewport_camera.cpp): a preset looks along its axis at the current
    // target, from just far enough for every particle to be in view; Default is the direction a
    // scene opens with, framing the particles as Frame All does
    void viewAlong(ViewPreset preset);
    void setProjection(Projection projection);
    // while on, the target follows the centroid of the selected particles in every new frame;
    // turned off, the camera stays where it is
    void setFollowSelection(bool on);
    bool followsSelection() const { return m_followSelection; }
    // whether every one of these particles (indices into the snapshot shown) is wholly in view
    bool particlesInView(const std::vector<int> &particles) const;

    // the nearest particle whose sphere the ray through a pixel (logical) meets, or else whose
    // centre is within kPickPixels of the pixel on screen, so that tiny or far particles can still
    // be picked; -1 for none
    int particleAt(const QPointF &pixel) const;
    // the spring whose line on screen passes nearest the pixel, within kPickPixels, of those drawn
    // (a spring hidden in the sheet is not picked); -1 for none. Particles hidden in the sheet are
    // picked, so that a cloth can still be selected and dragged by its particles
    int springAt(const QPointF &pixel) const;
    static constexpr float kPickPixels = 6.0f;

    // the current view drawn into an offscreen framebuffer of any size (device pixels), with the
    // same camera and the image's aspect ratio, and its lines as much wider than the view's as the
    // image is taller (lineScale), so that it looks like the view; a null image, and the reason in
    // error, if there is no GL context yet, the size is empty or larger than maxImageSide(), or GL
    // fails
    QImage renderImage(QSize size, QString *error = nullptr);
    // the largest side renderImage() accepts: the driver's renderbuffer, texture and viewport
    // limits (0 until GL is initialised)
    int maxImageSide() const { return m_maxImageSide; }
    // the width of a line drawn into a framebuffer this many pixels tall, over its width in the
    // view (kSpringPixels and the others are in the view's logical pixels)
    double lineScale(int framebufferHeight) const;

    // how many times the particle style was uploaded, and whether the framebuffer is multisampled
    int styleUploads() const { return m_styleUploads; }
    int samples() const { return m_samples; }

public slots:
    // points the camera at the particles from the current direction (keys F and Home)
    void frameAll();

signals:
    // seconds from the start of painting a frame to the frame on screen
    void frameTimeMeasured(double seconds);
    // a left press on a particle that no event filter took (a left press on empty space orbits)
    void particlePressed(int particle, Qt::KeyboardModifiers modifiers);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    // the particles' orientation attribute (in the bound VAO) read from `buffer`: one per instance,
    // or, while nothing turns, its one identity for every instance
    void pointOrientations(QOpenGLBuffer &buffer, bool perInstance);
    struct Gpu;  // programs, buffers and vertex arrays; exists only while GL is initialised
    enum class Drag { None, Orbit, Pan };

    void cleanupGL();
    // the whole scene as the camera sees it, into the bound framebuffer (paintGL and renderImage)
    // pixels: the framebuffer's size
    void drawScene(const Camera &camera, int samples, QSize pixels);
    // the sheet's triangles and what they hide, again when the triangles, the broken springs or
    // the layers changed (no GL)
    void refreshSurface();
    void uploadSnapshot();
    void uploadDecorations();
    void updateSceneBounds(const Sphere &bounds);
    // the particles' bounding sphere, or a unit sphere at the origin when there are none
    Sphere particleExtent() const;
    // the target to the selection's centroid, while following it
    void followSelection();

    Camera m_camera;
    std::shared_ptr<const core::Snapshot> m_snapshot;
    std::vector<core::PlaneDesc> m_planes;
    SteeringArrow m_steeringArrow;
    std::vector<int> m_selection;
    SpringHighlight m_springHighlight;
    int m_hoverParticle = -1;
    ParticleDrawing m_drawing = ParticleDrawing::Impostor;
    ViewLayers m_layers;
    SurfaceDraw m_surface;
    SurfaceKey m_surfaceKey;
    std::vector<std::uint8_t> m_hiddenParticles;  // per particle, by the sheet; empty when none
    std::vector<std::uint8_t> m_hiddenSprings;    // per spring, likewise
    bool m_surfaceChanged = true;                 // the sheet's indices are to be uploaded
    StrainLegend *m_legend = nullptr;

    // what is on the GPU
    std::unique_ptr<Gpu> m_gpu;
    bool m_positionsStale = true;  // a new snapshot has not been streamed yet
    StyleKey m_styleKey;
    bool m_selectionChanged = true;
    bool m_decorationsChanged = true;
    int m_styleUploads = 0;
    int m_samples = 0;
    int m_maxImageSide = 0;
    DrawnParticles m_drawn;       // which particles the instanced draws show
    std::vector<float> m_gathered;  // their styles or positions on the way to the buffers
    int m_exportSamples = 0;  // renderImage()'s multisampling: the view's, as far as the driver allows
    std::vector<float> m_springVertices;  // kept to reuse its memory
    std::vector<float> m_normals;         // likewise
    std::vector<float> m_surfacePositions;  // the particles' and the soft bodies' surface vertices

    // the scene's extent for the grid, the planes and the clip planes
    Sphere m_sceneBounds{QVector3D(0.0f, 0.0f, 0.0f), 1.0f};
    bool m_framed = false;
    bool m_autoFramed = false;  // framed by the first snapshot and not moved since
    bool m_followSelection = false;

    // mouse gestures and frame timing
    Drag m_drag = Drag::None;
    QPointF m_lastMouse;
    QElapsedTimer m_frameClock;
    bool m_frameTiming = false;
};

}  // namespace ui
