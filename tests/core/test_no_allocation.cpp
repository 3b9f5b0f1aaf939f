// No heap allocation inside a step, once its scratch arrays exist: malloc itself is counted
// (Eigen allocates through malloc, not operator new), for every integrator on a scene that runs
// every pass, small and large enough to be split across threads.
#include "core/model/generators.h"
#include "core/integrators/integrator.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>
#include <atomic>
#include <cstdlib>

#if defined(SPRINGLAB_UNDER_SANITIZERS)
#define SPRINGLAB_SANITIZED 1  // the sanitizers own malloc: these counters cannot take it over
#endif

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

[[maybe_unused]] void count()  // unused where a sanitizer owns malloc
{
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

#ifndef SPRINGLAB_SANITIZED
// glibc's own allocator under the usual names, counted: every allocation of the process (Eigen,
// the standard library, OpenMP) goes through these
extern "C" {
void *__libc_malloc(std::size_t size);
void *__libc_calloc(std::size_t count, std::size_t size);
void *__libc_realloc(void *pointer, std::size_t size);
void *__libc_memalign(std::size_t alignment, std::size_t size);

void *malloc(std::size_t size)
{
    count();
    return __libc_malloc(size);
}
void *calloc(std::size_t n, std::size_t size)
{
    count();
    return __libc_calloc(n, size);
}
void *realloc(void *pointer, std::size_t size)
{
    count();
    return __libc_realloc(pointer, size);
}
void *memalign(std::size_t alignment, std::size_t size)
{
    count();
    return __libc_memalign(alignment, size);
}
void *aligned_alloc(std::size_t alignment, std::size_t size)
{
    count();
    return __libc_memalign(alignment, size);
}
int posix_memalign(void **out, std::size_t alignment, std::size_t size)
{
    count();
    *out = __libc_memalign(alignment, size);
    return *out ? 0 : 12;  // ENOMEM
}
}
#endif

class TestNoAllocation : public QObject {
    Q_OBJECT

private slots:
    void counterSeesAnAllocation();
    void stepAllocatesNothing_data();
    void stepAllocatesNothing();
};

void TestNoAllocation::counterSeesAnAllocation()
{
#ifdef SPRINGLAB_SANITIZED
    QSKIP("built with a sanitizer that replaces malloc");
#endif
    // the check can fail: an Eigen array made while counting is seen
    g_allocations = 0;
    g_counting = true;
    Eigen::Matrix3Xd made(3, 1000);
    made.setZero();
    g_counting = false;
    QVERIFY(g_allocations.load() >= 1);
    QCOMPARE(made.sum(), 0.0);
}

void TestNoAllocation::stepAllocatesNothing_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<int>("size");
    QTest::addColumn<bool>("breakable");
    for (core::Integrator integrator : core::kIntegrators) {
        // left out: implicit-euler's and projective's sparse factorisations and triangular solves
        // (Eigen's) allocate their work arrays on every call
        if (integrator == core::Integrator::ImplicitEuler || integrator == core::Integrator::Projective)
            continue;
        const std::string_view name = core::integratorName(integrator);
        for (int size : {6, 70}) {
            // explicit Euler's large cloth needs thousands of sub-steps a step to stay whole (100 s
            // for these four steps); its update is the one loop the small cloth runs as well, and
            // the passes of the large one are those of every other integrator's row
            if (integrator == core::Integrator::ExplicitEuler && size > 6)
                continue;
            QTest::addRow("%.*s, %d × %d", int(name.size()), name.data(), size, size)
                << int(integrator) << size << false;
        }
        // vbd colours the torn cloth again after each break, which allocates
        if (integrator != core::Integrator::Vbd)
            QTest::addRow("%.*s, 6 × 6 tearing", int(name.size()), name.data()) << int(integrator) << 6 << true;
    }
}

void TestNoAllocation::stepAllocatesNothing()
{
#ifdef SPRINGLAB_SANITIZED
    QSKIP("built with a sanitizer that replaces malloc");
#endif
    QFETCH(int, integrator);
    QFETCH(int, size);
    QFETCH(bool, breakable);
    // a cloth over a floor with every pass on: gravity, drag, springs, an applied force, planes
    // and particle contacts
    core::ClothOptions options;
    options.rows = options.cols = size;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = static_cast<core::Integrator>(integrator);
    // explicit Euler is unstable on this cloth at its step, and a cloth flying apart at 1e10 m/s
    // sweeps every particle past every other: the contact solver's candidates then grow each step
    scene.settings.autoSubsteps = scene.settings.integrator == core::Integrator::ExplicitEuler;
    scene.settings.viscosity = 0.01;
    scene.settings.particleCollisions = size <= 6;  // all pairs at 4900 particles would be slow
    scene.planes = {core::PlaneDesc{{0.0, 1.0, 0.0}, 0.99}};
    // tearing: springs so brittle that the sag breaks them one after another
    if (breakable)
        for (core::SpringDesc &spring : scene.springs)
            spring.breakStrain = 1e-4;
    test::Sim sim = test::compile(scene);
    core::setAppliedForce(sim.state, 1, Eigen::Vector3d(0.0, 0.1, 0.0));

    // the first steps make the scratch arrays; after that, nothing
    for (int i = 0; i < 2; ++i)
        QVERIFY(sim.step());
    const std::size_t breaksBefore = sim.state.breaks.size();
    g_allocations = 0;
    g_counting = true;
    bool ok = true;
    // a tearing cloth runs on until springs have broken while counting
    for (int i = 0; i < 2 || (breakable && sim.state.breaks.size() == breaksBefore && i < 500); ++i)
        ok = sim.step() && ok;
    g_counting = false;
    QVERIFY(ok);
    QCOMPARE(g_allocations.load(), 0L);
    if (breakable)
        QVERIFY(sim.state.breaks.size() > breaksBefore);
}

QTEST_APPLESS_MAIN(TestNoAllocation)
#include "test_no_allocation.moc"
