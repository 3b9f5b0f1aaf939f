#pragma once
// `springlab-bench rolling`: single balls whose motion has a closed form (struck on felt, rolling
// down a slope, sliding down a steep one, struck with backspin), in the core with spin and, where
// libbullet-dev is installed, as Bullet's rotating spheres (bullet_spheres.h), side by side with the
// closed form: which engine it sides with. See rolling.cpp and docs/benchmarks.md.

#include <QString>
#include <QTextStream>

namespace bench {

// runs every scene in every engine, writes rolling.csv to outDir, prints the table; returns the
// exit code (0 done, 1 the CSV could not be written or the core blew up)
int runRolling(const QString &outDir, QTextStream &out);

}  // namespace bench
