#pragma once
// A light pass over JSON text for the three things QJsonDocument does not tell: where in the
// document a parse error happened (as a JSON path, "particles[3].mass"), which number literals
// were a negative zero (Qt's parser turns "-0" and "-0.0" into +0, which would break bit-exact
// round trips), and which key came twice in one object (Qt keeps the last without a word). It
// only tokenizes; it serves the files QJsonDocument reads (recordings) and the messages for a
// scene file's syntax errors. Scene files themselves are read by scene_reader.h.

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

// reads the string starting at the quote json[pos] into out; returns the position after its
// closing quote, or -1 when the text ends first. loneSurrogate: set when a \u escape is half of a
// UTF-16 pair without its other half (which Qt turns into a replacement character without a word)
qsizetype readJsonString(const QByteArray &json, qsizetype pos, QString &out, bool &loneSurrogate);

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

// the number of elements of each array that is a member of the top-level object, by key, counted
// as scanJson() counts them (topLevelArrays) but without keeping anything else: memory for the
// top-level keys only, so that a list over its limit is refused before anything is made for it
QHash<QString, qsizetype> countTopLevelArrays(const QByteArray &json);

// scans json up to (not past a token starting at) stopOffset, or to the end when it is negative;
// tolerant of malformed text: it stops at the first byte it cannot make sense of
JsonScan scanJson(const QByteArray &json, qsizetype stopOffset = -1);

}  // namespace io
