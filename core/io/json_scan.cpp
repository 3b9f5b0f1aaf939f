#include "json_scan.h"

#include <algorithm>
#include <vector>

namespace io {

namespace {

// one open object or array on the way down to the current value
struct Frame {
    bool array = false;
    qsizetype index = 0;    // arrays: the element being read
    bool empty = true;      // arrays: no element has started yet
    QString key;            // objects: the member being read
    bool haveKey = false;   // objects: a key has been read since '{' or ','
    bool expectKey = true;  // objects: the next string is a key
    std::vector<QString> keys;  // objects: the keys read so far (an object has few)
};

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool isNumberChar(char c)
{
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

// a number literal is a negative zero when it has a minus sign and no non-zero mantissa digit
bool isNegativeZero(const char *begin, const char *end)
{
    if (begin == end || *begin != '-')
        return false;
    for (const char *c = begin + 1; c != end && *c != 'e' && *c != 'E'; ++c)
        if (*c >= '1' && *c <= '9')
            return false;
    return true;
}

}  // namespace

qsizetype readJsonString(const QByteArray &json, qsizetype pos, QString &out, bool &loneSurrogate)
{
    out.clear();
    loneSurrogate = false;
    bool highPending = false;  // the last thing read was a \u escape of a high surrogate
    const qsizetype size = json.size();
    qsizetype runStart = ++pos;
    auto flushRun = [&](qsizetype runEnd) { out += QString::fromUtf8(json.constData() + runStart, runEnd - runStart); };
    while (pos < size && json[pos] != '"') {
        if (json[pos] != '\\') {
            loneSurrogate = loneSurrogate || highPending;
            highPending = false;
            ++pos;
            continue;
        }
        // an escape: decode it, then start a new raw run after it
        flushRun(pos);
        if (pos + 1 >= size)
            return -1;
        const char kind = json[pos + 1];
        pos += 2;
        switch (kind) {
        case 'b': out += QChar(u'\b'); break;
        case 'f': out += QChar(u'\f'); break;
        case 'n': out += QChar(u'\n'); break;
        case 'r': out += QChar(u'\r'); break;
        case 't': out += QChar(u'\t'); break;
        case 'u': {
            char16_t unit = 0;
            for (int digit = 0; digit < 4 && pos < size; ++digit, ++pos)
                unit = static_cast<char16_t>(unit * 16 + std::max(0, hexValue(json[pos])));
            out += QChar(unit);
            const bool high = QChar::isHighSurrogate(unit);
            const bool low = QChar::isLowSurrogate(unit);
            loneSurrogate = loneSurrogate || (highPending && !low) || (!highPending && low);
            highPending = high;
            break;
        }
        default:
            out += QLatin1Char(kind);  // \" \\ \/
            loneSurrogate = loneSurrogate || highPending;
            highPending = false;
            break;
        }
        runStart = pos;
    }
    flushRun(pos);
    loneSurrogate = loneSurrogate || highPending;
    return pos < size ? pos + 1 : -1;
}

namespace {

QString pathOf(const std::vector<Frame> &stack)
{
    QString path;
    for (const Frame &frame : stack) {
        if (frame.array)
            path = elementPath(path, frame.index);
        else if (frame.haveKey)
            path = memberPath(path, frame.key);
    }
    return path;
}

}  // namespace

QString memberPath(const QString &parent, const QString &key)
{
    const bool plain = !key.isEmpty() && !key.contains(u'.') && !key.contains(u'[') && !key.contains(u']') &&
                       !key.contains(u'"');
    if (!plain) {
        QString quoted = key;
        quoted.replace(u'\\', QStringLiteral("\\\\")).replace(u'"', QStringLiteral("\\\""));
        return parent + QStringLiteral("[\"") + quoted + QStringLiteral("\"]");
    }
    return parent.isEmpty() ? key : parent + u'.' + key;
}

QString elementPath(const QString &parent, qsizetype index)
{
    return parent + u'[' + QString::number(index) + u']';
}

JsonScan scanJson(const QByteArray &json, qsizetype stopOffset)
{
    JsonScan scan;
    std::vector<Frame> stack;
    const qsizetype size = json.size();
    const qsizetype stop = stopOffset < 0 ? size : std::min(stopOffset, size);
    QString text;
    bool unterminatedString = false;

    // one token per turn, after a byte order mark if there is one; a token that starts before
    // the stop is read whole
    qsizetype pos = json.startsWith("\xEF\xBB\xBF") ? 3 : 0;
    while (pos < stop) {
        const char c = json[pos];
        if (isSpace(c)) {
            ++pos;
        } else if (c == '{' || c == '[') {
            if (!stack.empty())
                stack.back().empty = false;
            Frame frame;
            frame.array = c == '[';
            stack.push_back(frame);
            ++pos;
        } else if (c == '}' || c == ']') {
            // a member array of the top-level object: how many elements it has
            if (stack.size() == 2 && stack.back().array && !stack.front().array && stack.front().haveKey)
                scan.topLevelArrays.insert(stack.front().key, stack.back().empty ? 0 : stack.back().index + 1);
            if (!stack.empty())
                stack.pop_back();
            ++pos;
        } else if (c == ',') {
            if (!stack.empty()) {
                Frame &top = stack.back();
                if (top.array) {
                    ++top.index;
                } else {
                    top.haveKey = false;
                    top.expectKey = true;
                }
            }
            ++pos;
        } else if (c == ':') {
            ++pos;
        } else if (c == '"') {
            if (!stack.empty() && stack.back().array)
                stack.back().empty = false;
            bool lone = false;
            pos = readJsonString(json, pos, text, lone);
            if (pos < 0) {
                unterminatedString = true;
                break;
            }
            // (a key's path is its parent's: the key itself is what is wrong)
            if (lone && scan.loneSurrogate.isNull())
                scan.loneSurrogate = pathOf(stack);
            if (!stack.empty() && !stack.back().array && stack.back().expectKey) {
                Frame &top = stack.back();
                top.key = text;
                top.haveKey = true;
                top.expectKey = false;
                if (std::find(top.keys.begin(), top.keys.end(), text) != top.keys.end()) {
                    if (scan.duplicateKey.isNull())
                        scan.duplicateKey = pathOf(stack);
                } else {
                    top.keys.push_back(text);
                }
            }
        } else if (isNumberChar(c)) {
            if (!stack.empty())
                stack.back().empty = false;
            const qsizetype start = pos;
            while (pos < size && isNumberChar(json[pos]))
                ++pos;
            // the last literal at a path wins, as it does in QJsonDocument
            const bool negativeZero = isNegativeZero(json.constData() + start, json.constData() + pos);
            if (negativeZero)
                scan.negativeZeros.insert(pathOf(stack));
            else if (!scan.negativeZeros.isEmpty())
                scan.negativeZeros.remove(pathOf(stack));
        } else if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
            if (!stack.empty())
                stack.back().empty = false;
            while (pos < size && ((json[pos] >= 'a' && json[pos] <= 'z') || (json[pos] >= 'A' && json[pos] <= 'Z')))
                ++pos;
        } else {
            break;
        }
    }
    scan.pathAtStop = pathOf(stack);
    scan.openAtStop = static_cast<int>(stack.size()) + (unterminatedString ? 1 : 0);
    return scan;
}

QHash<QString, qsizetype> countTopLevelArrays(const QByteArray &json)
{
    // per open object or array: an array, its index and whether an element has started; an
    // object, whether a key is due; only the top-level object's current key is kept
    struct Level {
        bool array = false;
        bool empty = true;
        bool expectKey = true;
        qsizetype index = 0;
    };
    QHash<QString, qsizetype> lengths;
    std::vector<Level> stack;
    QString topKey;
    bool haveTopKey = false;
    QString text;
    const char *bytes = json.constData();
    const qsizetype size = json.size();
    const auto started = [&] {
        if (!stack.empty())
            stack.back().empty = false;
    };

    qsizetype pos = json.startsWith("\xEF\xBB\xBF") ? 3 : 0;
    while (pos < size) {
        const char c = bytes[pos];
        if (isSpace(c) || c == ':') {
            ++pos;
        } else if (c == '{' || c == '[') {
            started();
            if (stack.empty())
                haveTopKey = false;
            stack.push_back({c == '[', true, true, 0});
            ++pos;
        } else if (c == '}' || c == ']') {
            if (stack.size() == 2 && stack.back().array && !stack.front().array && haveTopKey)
                lengths.insert(topKey, stack.back().empty ? 0 : stack.back().index + 1);
            if (!stack.empty())
                stack.pop_back();
            ++pos;
        } else if (c == ',') {
            if (!stack.empty()) {
                Level &top = stack.back();
                if (top.array)
                    ++top.index;
                else
                    top.expectKey = true;
                if (stack.size() == 1 && !top.array)
                    haveTopKey = false;
            }
            ++pos;
        } else if (c == '"') {
            if (!stack.empty() && stack.back().array)
                stack.back().empty = false;
            const bool topLevelKey = stack.size() == 1 && !stack.back().array && stack.back().expectKey;
            if (topLevelKey) {
                bool lone = false;
                pos = readJsonString(json, pos, text, lone);
                topKey = text;
                haveTopKey = true;
            } else {
                // skipped as readJsonString reads it: an escape takes the next byte, \u four more
                for (++pos; pos < size && bytes[pos] != '"';)
                    pos += bytes[pos] != '\\' ? 1 : pos + 1 >= size ? size : bytes[pos + 1] == 'u' ? 6 : 2;
                pos = pos < size ? pos + 1 : -1;
            }
            if (pos < 0)
                break;
            if (!stack.empty() && !stack.back().array)
                stack.back().expectKey = false;
        } else if (isNumberChar(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
            started();
            while (pos < size && (isNumberChar(bytes[pos]) || (bytes[pos] >= 'a' && bytes[pos] <= 'z') ||
                                  (bytes[pos] >= 'A' && bytes[pos] <= 'Z')))
                ++pos;
        } else {
            break;
        }
    }
    return lengths;
}

}  // namespace io
