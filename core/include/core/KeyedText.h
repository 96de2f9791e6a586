#pragma once
// A message that knows where it names a request's keys. Its text is in the request's own terms
// (JSON's: 'width', 'max_steps') and stays so on the wire; each front end words the keys its own
// way through `worded` (the command line's --size, -n; Python's width=), with no table of texts
// to rewrite: the positions say which words are keys, and the front end says what it calls them.
// Every layer writes its messages' keys this way (Error carries them, jobs::JobError too).

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb {

// A key the text names: where (bytes), and the key's path in the request ("trace.max_steps").
struct KeyMention {
    std::size_t offset = 0;
    std::size_t length = 0;
    std::string path;
};

class KeyedText {
public:
    KeyedText() = default;
    KeyedText(std::string text) : m_text(std::move(text)) {}
    KeyedText(const char* text) : m_text(text) {}
    KeyedText(std::string text, std::vector<KeyMention> keys) : m_text(std::move(text)), m_keys(std::move(keys)) {}

    const std::string& text() const { return m_text; }
    const std::vector<KeyMention>& keys() const { return m_keys; }

    KeyedText& operator+=(const KeyedText& more);
    friend KeyedText operator+(KeyedText left, const KeyedText& right) { return left += right; }

    // One key, quoted as JSON users see it: its last component ('max_steps' for trace.max_steps).
    static KeyedText key(std::string_view path);

private:
    std::string m_text;
    std::vector<KeyMention> m_keys;
};

// 'max_steps', naming the key at `path`.
inline KeyedText key(std::string_view path) { return KeyedText::key(path); }
// 'width', 'height': the keys a message is about, as its subject.
KeyedText keys(std::initializer_list<std::string_view> paths);
// "sign: unknown ..." (a lower layer's wording: a key, a colon) as a message about that key.
KeyedText keyedSubject(const std::string& message);

// What a front end calls the key at `path` ("--size" for width on the command line).
using KeyTerms = std::function<std::string(const std::string& path)>;

// `text` with every mentioned key in `term`'s words. Neighbouring keys that `term` words alike
// (width and height are both --size) are named once, with the ", " or "/" between them dropped.
std::string worded(const std::string& text, const std::vector<KeyMention>& keys, const KeyTerms& term);

// The last component of a key path: "max_steps" for "trace.max_steps".
std::string_view keyName(std::string_view path);

} // namespace sdfwb
