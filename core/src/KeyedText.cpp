// Messages that know where they name request keys, and their wording per front end.
#include <core/KeyedText.h>

#include <cctype>

namespace sdfwb {

KeyedText& KeyedText::operator+=(const KeyedText& more) {
    for (KeyMention mention : more.m_keys) {
        mention.offset += m_text.size();
        m_keys.push_back(std::move(mention));
    }
    m_text += more.m_text;
    return *this;
}

KeyedText KeyedText::key(std::string_view path) {
    KeyedText text("'" + std::string(keyName(path)) + "'");
    text.m_keys.push_back({0, text.m_text.size(), std::string(path)});
    return text;
}

KeyedText keys(std::initializer_list<std::string_view> paths) {
    KeyedText text;
    for (std::string_view path : paths) text += (text.text().empty() ? KeyedText() : KeyedText(", ")) + key(path);
    return text;
}

KeyedText keyedSubject(const std::string& message) {
    const std::size_t colon = message.find(": ");
    if (colon == std::string::npos || colon == 0) return message;
    for (std::size_t i = 0; i < colon; ++i) {
        const unsigned char c = static_cast<unsigned char>(message[i]);
        if (!std::islower(c) && !std::isdigit(c) && c != '_' && c != '.') return message;
    }
    return key(message.substr(0, colon)) + message.substr(colon);
}

std::string worded(const std::string& text, const std::vector<KeyMention>& keys, const KeyTerms& term) {
    std::string out;
    std::size_t at = 0;
    std::string previous; // the last key's words, while only a separator has followed it
    for (const KeyMention& mention : keys) {
        // Only a mention that is where it says, as the key's quoted name (a message read back from a
        // child could have been changed on the way).
        if (mention.offset < at || mention.offset > text.size() ||
            text.compare(mention.offset, mention.length, "'" + std::string(keyName(mention.path)) + "'") != 0)
            continue;
        const std::string between = text.substr(at, mention.offset - at);
        const std::string words = term(mention.path);
        if (!previous.empty() && words == previous && (between == ", " || between == "/")) {
            at = mention.offset + mention.length; // width, height -> --size once
            continue;
        }
        out += between;
        out += words;
        previous = words;
        at = mention.offset + mention.length;
    }
    return out + text.substr(at);
}

std::string_view keyName(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

} // namespace sdfwb
