#pragma once
// A light pass over JSON text for the two things QJsonDocument does not tell: where in the
// document a parse error happened (as a JSON path, "particles[3].mass"), and which number
// literals were a negative zero (Qt's parser turns "-0" and "-0.0" into +0, which would break
// bit-exact round trips). It only tokenizes; QJsonDocument stays the parser of record.

#include <QByteArray>
#include <QSet>
#include <QString>

namespace io {

// "settings" + "timeStep" -> "settings.timeStep"; "" + "format" -> "format"
QString memberPath(const QString &parent, const QString &key);

// "particles" + 3 -> "particles[3]"
QString elementPath(const QString &parent, qsizetype index);

struct JsonScan {
    QSet<QString> negativeZeros;  // paths of the number literals that are a negative zero
    QString pathAtStop;           // path of the value being read at stopOffset ("" at top level)
    int openAtStop = 0;           // objects and arrays still open there (or an unterminated string)
};

// scans json up to (not past a token starting at) stopOffset, or to the end when it is negative;
// tolerant of malformed text: it stops at the first byte it cannot make sense of
JsonScan scanJson(const QByteArray &json, qsizetype stopOffset = -1);

}  // namespace io
