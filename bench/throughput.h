#pragma once
// `springlab-bench throughput`: run time per step of the core against two reference
// implementations written here (plain_cloth.h, naive_cloth.h) and, where libbullet-dev is
// installed, Bullet's soft-body cloth (bullet_cloth.h), measured in the same run, and against the
// machine's memory bandwidth, also measured in the same run (bandwidth.h); see throughput.cpp and
// docs/benchmarks.md.

#include <QString>
#include <QTextStream>

namespace bench {

struct ThroughputOptions {
    QString outDir = QStringLiteral(".");  // where throughput.csv and throughput.png go
    bool quick = false;                    // the smallest scenes and short timings: a smoke test only
};

// measures every scene, writes throughput.csv and throughput.png, prints the summary; returns the
// exit code (0 done, 1 a file could not be written or a reference disagreed with the core)
int runThroughput(const ThroughputOptions &options, QTextStream &out);

}  // namespace bench
