#pragma once
// `springlab-bench cloth-contacts`: a sheet crumpling on the floor and one draping over a sphere,
// 64 x 64 and 200 x 200, in the core with its triangle collisions, in the core without them, and,
// where libbullet-dev is installed, as Bullet's soft-body cloth with its self-collision on
// (bullet_sheet.h), side by side in one run: the crossings counted after every step (an edge of the
// sheet through one of its triangles), the time a step, and the core's share of it that the
// triangle collisions take. See cloth_contacts.cpp and docs/benchmarks.md.

#include <QString>
#include <QTextStream>

#include <vector>

namespace bench {

struct ClothContactsOptions {
    QString outDir = QStringLiteral(".");  // where cloth-contacts.csv goes
    bool quick = false;                    // a 16 x 16 sheet, a few steps: a smoke test only
    std::vector<int> sizes;                // particles a side; empty: 64 and 200
    double seconds = 0.0;                  // simulated time a run; 0: 2 s at 64, 0.5 s at 200
};

// runs every scene at every size in every engine, writes cloth-contacts.csv, prints the table;
// returns the exit code (0 done, 1 the CSV could not be written or the core blew up)
int runClothContacts(const ClothContactsOptions &options, QTextStream &out);

}  // namespace bench
