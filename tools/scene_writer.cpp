#include "tools/scene_writer.h"

#include "core/io/scene_file.h"
#include "core/model/validate.h"

#include <QDir>
#include <cstdio>

namespace tools {

int writeScenes(int argc, char **argv, const std::vector<core::SceneDesc> &scenes)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s DIRECTORY\n", argv[0]);
        return 2;
    }
    const QDir dir(QString::fromLocal8Bit(argv[1]));
    if (!dir.mkpath(QStringLiteral("."))) {
        std::fprintf(stderr, "cannot create %s\n", argv[1]);
        return 1;
    }
    for (const core::SceneDesc &scene : scenes) {
        if (auto problem = core::findProblem(scene)) {
            std::fprintf(stderr, "%s: %s: %s\n", scene.name.c_str(), problem->path.c_str(), problem->message.c_str());
            return 1;
        }
        const QString path = dir.filePath(QString::fromStdString(scene.name) + ".json");
        const io::SaveResult saved = io::saveScene(path, scene);
        if (!saved.ok()) {
            std::fprintf(stderr, "%s\n", qPrintable(saved.error));
            return 1;
        }
        std::printf("wrote %s\n", qPrintable(path));
    }
    return 0;
}

}  // namespace tools
