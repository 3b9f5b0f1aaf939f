#include "json_pull.h"

#include "json_scan.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace io {

namespace {

// an object with more keys than this finds a duplicate through a hash set, not by looking at each
constexpr std::size_t kFewKeys = 16;

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// QJsonDocument's reading of one token alone, as the only element of an array; false where it
// refuses the token
bool qtReads(std::string_view token, QJsonValue &out)
{
    QByteArray text;
    text.reserve(static_cast<qsizetype>(token.size()) + 2);
    text += '[';
    text.append(token.data(), static_cast<qsizetype>(token.size()));
    text += ']';
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !document.isArray() || document.array().size() != 1)
        return false;
    out = document.array().at(0);
    return true;
}

// Qt reads "-0" as +0; the literal's sign is given back, as json_scan.h does for the whole text
bool isNegativeZeroLiteral(std::string_view token)
{
    if (token.empty() || token.front() != '-')
        return false;
    for (const char c : token.substr(1)) {
        if (c == 'e' || c == 'E')
            break;
        if (c >= '1' && c <= '9')
            return false;
    }
    return true;
}

// a string's text starts with U+FEFF, written or escaped: Qt's text drops it, its keys keep it
bool startsWithByteOrderMark(std::string_view text)
{
    if (text.starts_with("\xEF\xBB\xBF"))
        return true;
    if (!text.starts_with("\\u") || text.size() < 6)
        return false;
    unsigned unit = 0;
    for (const char c : text.substr(2, 4)) {
        const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (digit < 0)
            return false;
        unit = unit * 16 + unsigned(digit);
    }
    return unit == 0xFEFF;
}

int hexDigit(char c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
}

// the UTF-16 unit of the four hex digits of the \u escape at text[i], or -1
int unitAt(std::string_view text, std::size_t i)
{
    if (i + 6 > text.size() || text[i] != '\\' || text[i + 1] != 'u')
        return -1;
    int unit = 0;
    for (std::size_t k = i + 2; k < i + 6; ++k) {
        const int digit = hexDigit(text[k]);
        if (digit < 0)
            return -1;
        unit = unit * 16 + digit;
    }
    return unit;
}

bool isHighSurrogate(int unit)
{
    return unit >= 0xD800 && unit <= 0xDBFF;
}

bool isLowSurrogate(int unit)
{
    return unit >= 0xDC00 && unit <= 0xDFFF;
}

// a string's text as written between its quotes, checked as QJsonDocument (Qt 6.4) reads it:
// UTF-8 throughout, a \u escape with four hex digits; any other escaped ASCII character stands
// for itself, as Qt allows. lone: a \u escape is half of a UTF-16 pair
bool checkWritten(std::string_view written, bool &lone)
{
    lone = false;
    for (std::size_t i = 0; i < written.size(); ++i) {
        if (written[i] != '\\')
            continue;
        if (i + 1 == written.size() || static_cast<unsigned char>(written[i + 1]) >= 0x80)
            return false;
        if (written[i + 1] != 'u') {
            ++i;
            continue;
        }
        const int unit = unitAt(written, i);
        if (unit < 0)
            return false;
        if (isHighSurrogate(unit) && isLowSurrogate(unitAt(written, i + 6)))
            i += 6;
        else if (isHighSurrogate(unit) || isLowSurrogate(unit))
            lone = true;
        i += 5;
    }
    return QByteArrayView(written.data(), static_cast<qsizetype>(written.size())).isValidUtf8();
}

// the text of a string that checkWritten() passed, as UTF-8; half a UTF-16 pair becomes U+FFFD
QByteArray decodeWritten(std::string_view written)
{
    QByteArray out;
    out.reserve(static_cast<qsizetype>(written.size()));
    const auto append = [&out](char32_t code) {
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xF0 | (code >> 18));
            out += char(0x80 | ((code >> 12) & 0x3F));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    };
    for (std::size_t i = 0; i < written.size(); ++i) {
        const char c = written[i];
        if (c != '\\') {
            out += c;
            continue;
        }
        const char escaped = written[++i];
        switch (escaped) {
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
            const int unit = unitAt(written, i - 1);
            const int low = unitAt(written, i + 5);
            if (isHighSurrogate(unit) && isLowSurrogate(low)) {
                append(0x10000 + ((char32_t(unit) - 0xD800) << 10) + (char32_t(low) - 0xDC00));
                i += 6;
            } else {
                append(isHighSurrogate(unit) || isLowSurrogate(unit) ? 0xFFFD : char32_t(unit));
            }
            i += 4;
            break;
        }
        default: out += escaped;  // '"', '\\', '/', and what Qt lets stand for itself
        }
    }
    return out;
}

}  // namespace

JsonPull::JsonPull(QByteArrayView json, JsonStrings strings)
    : m_begin(json.data()), m_pos(json.data()), m_end(json.data() + json.size()), m_strings(strings)
{
    if (json.startsWith("\xEF\xBB\xBF"))
        m_pos += 3;
}

JsonToken JsonPull::fail()
{
    if (m_errorOffset < 0)
        m_errorOffset = m_pos - m_begin;
    return JsonToken::Error;
}

void JsonPull::skipSpace()
{
    while (m_pos != m_end && (*m_pos == ' ' || *m_pos == '\t' || *m_pos == '\n' || *m_pos == '\r'))
        ++m_pos;
}

QString JsonPull::pathHere() const
{
    QString path;
    for (std::size_t level = 0; level < m_depth; ++level) {
        const Frame &frame = m_frames[level];
        if (!frame.object)
            path = elementPath(path, frame.index);
        else if (frame.haveKey)
            path = memberPath(path, QString::fromUtf8(frame.key.data(), static_cast<qsizetype>(frame.key.size())));
    }
    return path;
}

QString JsonPull::text() const
{
    if (m_isWritten)
        return QString::fromUtf8(utf8());
    return m_isPlain ? QString::fromLatin1(m_plain.data(), static_cast<qsizetype>(m_plain.size())) : m_decoded;
}

bool JsonPull::isText(QLatin1StringView expected) const
{
    if (m_isWritten)
        return !m_lostMark && text() == expected;
    return m_isPlain ? m_plain == std::string_view(expected.data(), static_cast<std::size_t>(expected.size()))
                     : !m_lostMark && m_decoded == expected;
}

QByteArray JsonPull::utf8() const
{
    if (m_isPlain)
        return QByteArray(m_plain.data(), static_cast<qsizetype>(m_plain.size()));
    if (!m_isWritten)
        return m_decoded.toUtf8();
    return decodeWritten(m_written);
}

// a string at m_pos (its opening quote); plain text is kept as a view, anything else is decoded
// by QJsonDocument so that the text is exactly what it would give, or (a value, with
// JsonStrings::Check) checked as QJsonDocument would check it and kept as written
bool JsonPull::readString(bool key)
{
    const char *start = m_pos++;
    bool plain = true;
    while (m_pos != m_end && *m_pos != '"') {
        const auto c = static_cast<unsigned char>(*m_pos);
        if (c == '\\') {
            plain = false;
            if (++m_pos == m_end)
                return false;
        } else if (c < 0x20 || c >= 0x80) {
            plain = false;
        }
        ++m_pos;
    }
    if (m_pos == m_end)
        return false;
    ++m_pos;
    m_isPlain = plain;
    m_isWritten = false;
    m_lostMark = false;
    if (plain) {
        m_plain = std::string_view(start + 1, static_cast<std::size_t>(m_pos - start - 2));
        return true;
    }
    if (!key && m_strings == JsonStrings::Check) {
        const std::string_view written(start + 1, static_cast<std::size_t>(m_pos - start - 2));
        bool lone = false;
        if (!checkWritten(written, lone))
            return false;
        m_written = written;
        m_isWritten = true;
        m_lostMark = startsWithByteOrderMark(written);
        if (lone && m_loneSurrogate.isNull())
            m_loneSurrogate = pathHere();
        return true;
    }
    const std::string_view token(start, static_cast<std::size_t>(m_pos - start));
    QJsonValue value;
    if (!qtReads(token, value) || !value.isString())
        return false;
    m_decoded = value.toString();
    m_lostMark = startsWithByteOrderMark(token.substr(1));
    QString ignored;
    bool lone = false;
    readJsonString(QByteArray::fromRawData(token.data(), static_cast<qsizetype>(token.size())), 0, ignored, lone);
    if (lone && m_loneSurrogate.isNull())
        m_loneSurrogate = pathHere();
    return true;
}

// a number at m_pos, delimited as Qt delimits it; plain JSON numbers are converted here (to the
// nearest double, as Qt does), anything else is left to QJsonDocument
bool JsonPull::readNumber()
{
    const char *start = m_pos;
    const char *p = m_pos;
    bool strict = true;
    if (*p == '-')
        ++p;
    if (p != m_end && *p == '0') {
        ++p;
    } else {
        const char *digits = p;
        while (p != m_end && isDigit(*p))
            ++p;
        strict = strict && p != digits;
    }
    if (p != m_end && *p == '.') {
        const char *digits = ++p;
        while (p != m_end && isDigit(*p))
            ++p;
        strict = strict && p != digits;
    }
    if (p != m_end && (*p == 'e' || *p == 'E')) {
        if (++p != m_end && (*p == '+' || *p == '-'))
            ++p;
        const char *digits = p;
        while (p != m_end && isDigit(*p))
            ++p;
        strict = strict && p != digits;
    }
    // a number may not end the text (nor can it end a document of a scene)
    if (p == m_end)
        return false;
    m_pos = p;

    // the common case: a plain number that converts to a normal double or to zero
    if (strict) {
        const auto [end, ec] = std::from_chars(start, p, m_number);
        if (ec == std::errc() && end == p &&
            (m_number == 0.0 || std::abs(m_number) >= std::numeric_limits<double>::min()))
            return true;
    }
    const std::string_view token(start, static_cast<std::size_t>(p - start));
    QJsonValue value;
    if (!qtReads(token, value) || !value.isDouble())
        return false;
    m_number = value.toDouble();
    if (m_number == 0.0 && isNegativeZeroLiteral(token))
        m_number = -0.0;
    return true;
}

// the key just read becomes the current member of the innermost object; a key that came before
// in the same object is noted (the first one in the text)
bool JsonPull::addKey()
{
    Frame &frame = m_frames[m_depth - 1];
    std::string_view key = m_plain;
    if (!m_isPlain) {
        frame.decodedKeys.push_back(m_decoded.toStdString());
        key = frame.decodedKeys.back();
    }
    frame.key = key;
    frame.haveKey = true;
    bool seen = false;
    if (frame.manyKeys.empty() && frame.keys.size() < kFewKeys) {
        seen = std::find(frame.keys.begin(), frame.keys.end(), key) != frame.keys.end();
        if (!seen)
            frame.keys.push_back(key);
    } else {
        if (frame.manyKeys.empty())
            frame.manyKeys.insert(frame.keys.begin(), frame.keys.end());
        seen = !frame.manyKeys.insert(key).second;
    }
    if (seen && m_duplicateKey.isNull())
        m_duplicateKey = pathHere();
    return true;
}

JsonToken JsonPull::afterValue(JsonToken token)
{
    if (m_depth == 0)
        m_done = true;
    else
        m_frames[m_depth - 1].want = Frame::Want::Separator;
    return token;
}

// a value at m_pos: the first token of an object or array, or a whole scalar
JsonToken JsonPull::value()
{
    if (m_pos == m_end)
        return fail();
    const char c = *m_pos;
    // Qt 6.4 reads only an object or an array at the top level
    if (m_depth == 0 && c != '{' && c != '[')
        return fail();
    if (c == '{' || c == '[') {
        if (m_frames.size() == m_depth)
            m_frames.emplace_back();
        Frame &frame = m_frames[m_depth++];
        frame.object = c == '{';
        frame.want = Frame::Want::First;
        frame.index = 0;
        frame.haveKey = false;
        frame.keys.clear();
        frame.manyKeys.clear();
        frame.decodedKeys.clear();
        ++m_pos;
        return frame.object ? JsonToken::BeginObject : JsonToken::BeginArray;
    }
    if (c == '"')
        return readString(false) ? afterValue(JsonToken::String) : fail();
    // true, false, null
    const std::string_view rest(m_pos, static_cast<std::size_t>(m_end - m_pos));
    for (const auto &[word, token] : {std::pair{std::string_view("true"), JsonToken::True},
                                      std::pair{std::string_view("false"), JsonToken::False},
                                      std::pair{std::string_view("null"), JsonToken::Null}})
        if (rest.starts_with(word)) {
            m_pos += word.size();
            return afterValue(token);
        }
    if (c == 't' || c == 'f' || c == 'n')
        return fail();
    // anything else Qt tries as a number (it reads ".5" as 0.5)
    return readNumber() ? afterValue(JsonToken::Number) : fail();
}

JsonToken JsonPull::next()
{
    if (m_errorOffset >= 0)
        return JsonToken::Error;
    skipSpace();
    if (m_depth == 0)
        return !m_done ? value() : m_pos == m_end ? JsonToken::End : fail();
    if (m_pos == m_end)
        return fail();

    // the end of the innermost object or array, or the separator before its next member
    Frame &frame = m_frames[m_depth - 1];
    const char close = frame.object ? '}' : ']';
    if (frame.want == Frame::Want::First || frame.want == Frame::Want::Separator) {
        if (*m_pos == close) {
            ++m_pos;
            const bool object = frame.object;
            --m_depth;
            return afterValue(object ? JsonToken::EndObject : JsonToken::EndArray);
        }
        if (frame.want == Frame::Want::Separator) {
            if (*m_pos != ',')
                return fail();
            ++m_pos;
            skipSpace();
            if (frame.object)
                frame.haveKey = false;
            else
                ++frame.index;
        }
        frame.want = frame.object ? Frame::Want::Key : Frame::Want::Value;
    }

    // a member's key and its colon
    if (frame.want == Frame::Want::Key) {
        if (m_pos == m_end || *m_pos != '"' || !readString(true) || !addKey())
            return fail();
        skipSpace();
        if (m_pos == m_end || *m_pos != ':')
            return fail();
        ++m_pos;
        m_frames[m_depth - 1].want = Frame::Want::Value;
        return JsonToken::Key;
    }
    return value();
}

bool JsonPull::skipRest(JsonToken first)
{
    if (first != JsonToken::BeginObject && first != JsonToken::BeginArray)
        return first != JsonToken::Error;
    for (int open = 1; open > 0;) {
        const JsonToken token = next();
        if (token == JsonToken::Error)
            return false;
        if (token == JsonToken::BeginObject || token == JsonToken::BeginArray)
            ++open;
        else if (token == JsonToken::EndObject || token == JsonToken::EndArray)
            --open;
    }
    return true;
}

}  // namespace io
