// libFuzzer entry point for the scene loader: any input that breaks a property of
// checkSceneInput() aborts, so libFuzzer saves it as an artifact (tools/fuzz.sh runs it).
// The loader needs no QCoreApplication: it only uses QtCore's JSON and strings.

#include "scene_input_check.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    // raw data, not a copy, so that AddressSanitizer sees a read one byte past the input
    const QByteArray bytes = QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    const QString problem = fuzz::checkSceneInput(bytes);
    if (!problem.isEmpty()) {
        std::fprintf(stderr, "scene input check failed: %s\n", problem.toUtf8().constData());
        std::abort();
    }
    return 0;
}
