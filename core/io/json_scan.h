#pragma once
// A light pass over JSON text for the three things QJsonDocument does not tell: where in the
// document a parse error happened (as a JSON path, "particles[3].mass"), which number literals
// were a negative zero (Qt's parser turns "-0" and "-0.0" into +0, which would break bit-exact
// round trips), and which key came twice in one object (Qt keeps the last without a word). It
// only tokenizes; QJsonDocument stays the parser of record.

#include <QByteArray>
#include <QHash>
#include <QSet>
#include <QString>

namespace io {

// "settings" + "timeStep" -> "settings.timeStep"; "" + "format" -> "format". A key that could be
// read as a path ("particles[1].velocity", one with a '.', '[', ']' or '"', or an empty one) is
// quoted, ["particles[1].velocity"], so that no key can name another member's path
QString memberPath(const QString &parent, const QString &key);

// "particles" + 3 -> "particles[3]"
QString elementPath(const QString &parent, qsizetype index);

struct JsonScan {
    QSet<QString> negativeZeros;  // paths of the number literals that are a negative zero
    QString duplicateKey;         // path of the first member whose key came before in its object
    QString loneSurrogate;        // path of the first string with half a UTF-16 pair, \ud800 alone
    // the number of elements of each array that is a member of the top-level object, by key
    // ("particles": 3), so that a list over its limit is refused before the parser builds it
    QHash<QString, qsizetype> topLevelArrays;
    QString pathAtStop;           // path of the value being read at stopOffset ("" at top level)
    int openAtStop = 0;           // objects and arrays still open there (or an unterminated string)
};

// scans json up to (not past a token starting at) stopOffset, or to the end when it is negative;
// tolerant of malformed text: it stops at the first byte it cannot make sense of
JsonScan scanJson(const QByteArray &json, qsizetype stopOffset = -1);

}  // namespace io
