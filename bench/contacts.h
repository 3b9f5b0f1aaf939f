#pragma once
// `springlab-bench contacts`: the contact scenes (a column, a pyramid, a pile in a box at 1
// and at 4 sub-steps, a heap poured onto the floor; contact_scenes.h) run in the core and, where
// libbullet-dev is installed, in Bullet's rigid spheres (bullet_spheres.h) side by side in one run:
// whether each stack stands, when each pile settles, the deepest overlap left, the heap's angle of
// repose, and the CPU time per step. See contacts.cpp and docs/benchmarks.md.

#include <QString>
#include <QTextStream>

namespace bench {

struct ContactsOptions {
    QString outDir = QStringLiteral(".");  // where contacts.csv and contacts.png go
    bool quick = false;                    // short runs of smaller scenes: a smoke test only
};

// runs every scene in every engine, writes contacts.csv and contacts.png, prints the summary;
// returns the exit code (0 done, 1 a file could not be written or the core blew up)
int runContacts(const ContactsOptions &options, QTextStream &out);

}  // namespace bench
