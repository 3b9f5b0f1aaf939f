#pragma once
// What one scene-loader input must satisfy, whatever its bytes: shared by the libFuzzer target
// (fuzz_scene_loader.cpp) and the regression test over tests/io/corpus (test_fuzz_corpus.cpp), so
// that a crash the fuzzer finds stays found.

#include <QByteArray>
#include <QString>

namespace fuzz {

// the source name the check loads under; every error message must start with it
inline constexpr char kSourceName[] = "input.json";

// loads the bytes with small limits and checks: the loader returns (no crash, no hang); a failure
// has a message naming the source; a success passes core::findProblem(), has unit plane normals,
// saves to JSON that loads again and saves to the same bytes, and compiles and runs a few steps
// (skipped when the scene asks for more work than a fuzz input may take). Returns an empty string
// when all hold, else which one failed.
QString checkSceneInput(const QByteArray &bytes);

}  // namespace fuzz
