// save_loop OUT: saves two different scenes to OUT, one after the other, for ever, printing
// "saving" once before the first save and "saved" after each. test_atomic_save kills it (SIGKILL) at random moments and
// checks what it left behind.
#include "core/model/generators.h"
#include "core/io/scene_file.h"

#include <QCoreApplication>
#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: save_loop OUT\n");
        return 2;
    }
    const QString out = QString::fromLocal8Bit(argv[1]);
    // two cloths of different sizes: files of different lengths, big enough that a kill often
    // lands in the middle of writing one
    core::ClothOptions options;
    options.rows = options.cols = 30;
    const core::SceneDesc first = core::makeCloth(options);
    options.rows = options.cols = 25;
    const core::SceneDesc second = core::makeCloth(options);
    std::printf("saving\n");
    std::fflush(stdout);
    for (unsigned long i = 0;; ++i) {
        const io::SaveResult saved = io::saveScene(out, i % 2 == 0 ? first : second);
        if (!saved.ok()) {
            std::fprintf(stderr, "save_loop: %s\n", qPrintable(saved.error));
            return 1;
        }
        std::printf("saved\n");
        std::fflush(stdout);
    }
}
