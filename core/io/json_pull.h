#pragma once
// A pull reader of JSON text: the caller asks for one token at a time and keeps only what it
// wants, so that reading a file needs memory for the file's bytes and for what is taken from them,
// never for a tree of the whole document. It checks the grammar as it goes and agrees with
// QJsonDocument (Qt 6) on what it accepts and on the values: a token it is not sure of (a number
// outside plain JSON's grammar, a string with escapes or bytes outside printable ASCII) is handed
// to QJsonDocument alone. On any doubt it says Error, and the caller asks QJsonDocument for the
// message. It also notes the two things QJsonDocument does not tell: the first key that comes
// twice in one object and the first string with a lone UTF-16 surrogate, each as a JSON path.

#include <QByteArray>
#include <QByteArrayView>
#include <QLatin1StringView>
#include <QString>

#include <deque>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace io {

enum class JsonToken { BeginObject, EndObject, BeginArray, EndArray, Key, String, Number, True, False, Null, End, Error };

// how a string value is taken: decoded at once as QJsonDocument decodes it (a scene's few short
// strings), or only checked, and decoded when asked (a recording's scenes: each the text of a
// whole scene file, which QJsonDocument would copy twice over)
enum class JsonStrings { Decode, Check };

class JsonPull {
public:
    // json must outlive the reader; a UTF-8 byte order mark at the start is skipped
    explicit JsonPull(QByteArrayView json, JsonStrings strings = JsonStrings::Decode);

    // the next token; Error once the text breaks the grammar (and from then on)
    JsonToken next();

    // skips the rest of a value whose first token was just read (a whole object or array); false
    // when the text breaks the grammar before its end
    bool skipRest(JsonToken first);

    // after a Key or a String: its text; plainText() is set when it had no escapes and only
    // printable ASCII (then text() is made from it on demand)
    QString text() const;
    bool isText(QLatin1StringView expected) const;
    // the text began with a byte order mark, which Qt drops from text() but keeps in a key, so
    // that such a key is none of the known ones (nor warned about when it would be one)
    bool lostMark() const { return m_lostMark; }
    // after a Key or a String: its text as UTF-8 (with JsonStrings::Check, decoded now; half of a
    // UTF-16 pair becomes U+FFFD, and loneSurrogate() names it)
    QByteArray utf8() const;
    // after a Number: its value, the sign of zero kept
    double number() const { return m_number; }
    // the offset just past the last token read (after a BeginObject or BeginArray, past its bracket)
    qsizetype offset() const { return m_pos - m_begin; }

    // where the grammar first broke, as a byte offset (-1: it has not)
    qsizetype errorOffset() const { return m_errorOffset; }
    // the path of the first member whose key came before in its object, and of the first string
    // with half a UTF-16 pair; null when there is none
    const QString &duplicateKey() const { return m_duplicateKey; }
    const QString &loneSurrogate() const { return m_loneSurrogate; }

private:
    // one open object or array
    struct Frame {
        bool object = false;
        enum class Want { First, Key, Value, Separator } want = Want::First;
        qsizetype index = 0;                    // arrays: the element being read
        bool haveKey = false;                   // objects: a key has been read for the member
        std::string_view key;                   // objects: that key, as UTF-8
        std::vector<std::string_view> keys;     // objects: the keys so far (few, in most objects)
        std::unordered_set<std::string_view> manyKeys;  // the same, once there are many
        std::deque<std::string> decodedKeys;    // storage of keys that had escapes
    };

    JsonToken fail();
    JsonToken value();
    JsonToken afterValue(JsonToken token);
    bool readString(bool key);
    bool readNumber();
    bool addKey();
    QString pathHere() const;
    void skipSpace();

    const char *m_begin;
    const char *m_pos;
    const char *m_end;
    // never shrinks, so that a frame's buffers are reused; a deque, so that a frame never moves
    // (its keys are views of its own storage)
    std::deque<Frame> m_frames;
    std::size_t m_depth = 0;
    bool m_done = false;          // the top-level value has been read
    qsizetype m_errorOffset = -1;

    JsonStrings m_strings;

    // the last string or key: a view of plain text, or the text QJsonDocument decoded, or (a
    // string checked but not decoded) its text as written between the quotes
    std::string_view m_plain;
    bool m_isPlain = true;
    QString m_decoded;
    std::string_view m_written;
    bool m_isWritten = false;
    bool m_lostMark = false;
    double m_number = 0.0;

    QString m_duplicateKey;
    QString m_loneSurrogate;
};

}  // namespace io
