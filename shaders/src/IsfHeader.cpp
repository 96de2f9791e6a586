#include "IsfHeader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace sdfwb::shaders::detail {

namespace {

// A JSON value with where it lies in the text: only what the header reader needs.
struct Value {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    double number = 0.0;
    std::string string;
    std::vector<Value> items;      // an array's
    std::vector<std::string> keys; // an object's members, in order: their keys and values
    std::vector<Value> members;
    std::size_t offset = 0, length = 0;
};

class Reader {
public:
    Reader(const std::string& text, std::size_t begin, std::size_t end) : m_text(text), m_at(begin), m_end(end) {}

    bool value(Value& out, int depth = 0) {
        skip();
        if (m_at >= m_end || depth > 32) return false;
        out.offset = m_at;
        const char c = m_text[m_at];
        if (c == '{') {
            out.kind = Value::Kind::Object;
            ++m_at;
            for (;;) {
                skip();
                if (m_at < m_end && m_text[m_at] == '}') break;
                Value key;
                if (!string(key)) return false;
                skip();
                if (m_at >= m_end || m_text[m_at] != ':') return false;
                ++m_at;
                Value member;
                if (!value(member, depth + 1)) return false;
                out.keys.push_back(key.string);
                out.members.push_back(std::move(member));
                skip();
                if (m_at < m_end && m_text[m_at] == ',')
                    ++m_at; // a comma before `}` too
                else if (m_at >= m_end || m_text[m_at] != '}')
                    return false;
            }
            ++m_at;
        } else if (c == '[') {
            out.kind = Value::Kind::Array;
            ++m_at;
            for (;;) {
                skip();
                if (m_at < m_end && m_text[m_at] == ']') break;
                Value item;
                if (!value(item, depth + 1)) return false;
                out.items.push_back(std::move(item));
                skip();
                if (m_at < m_end && m_text[m_at] == ',')
                    ++m_at;
                else if (m_at >= m_end || m_text[m_at] != ']')
                    return false;
            }
            ++m_at;
        } else if (c == '"') {
            return string(out);
        } else if (word("true") || word("false") || word("null")) {
            out.kind = m_text[out.offset] == 'n' ? Value::Kind::Null : Value::Kind::Bool;
            out.number = m_text[out.offset] == 't' ? 1.0 : 0.0;
        } else {
            if (c != '-' && !std::isdigit(static_cast<unsigned char>(c))) return false; // JSON's numbers only
            char* stop = nullptr;
            const std::string digits = m_text.substr(m_at, std::min<std::size_t>(64, m_end - m_at));
            out.number = std::strtod(digits.c_str(), &stop);
            if (stop == digits.c_str() || !std::isfinite(out.number)) return false;
            out.kind = Value::Kind::Number;
            m_at += std::size_t(stop - digits.c_str());
        }
        out.length = m_at - out.offset;
        return true;
    }

private:
    void skip() {
        while (m_at < m_end && std::isspace(static_cast<unsigned char>(m_text[m_at]))) ++m_at;
    }
    bool word(const char* w) {
        const std::size_t n = std::char_traits<char>::length(w);
        if (m_text.compare(m_at, n, w) != 0 || m_at + n > m_end) return false;
        m_at += n;
        return true;
    }
    bool string(Value& out) {
        if (m_at >= m_end || m_text[m_at] != '"') return false;
        out.kind = Value::Kind::String;
        out.offset = m_at++;
        for (; m_at < m_end && m_text[m_at] != '"'; ++m_at) {
            if (m_text[m_at] == '\\' && m_at + 1 < m_end) ++m_at;
            out.string += m_text[m_at];
        }
        if (m_at >= m_end) return false;
        ++m_at;
        out.length = m_at - out.offset;
        return true;
    }

    const std::string& m_text;
    std::size_t m_at, m_end;
};

const Value* member(const Value& object, const std::string& key) {
    for (std::size_t i = 0; i < object.keys.size(); ++i)
        if (object.keys[i] == key) return &object.members[i];
    return nullptr;
}

std::vector<double> numbers(const Value* value) {
    if (!value) return {};
    if (value->kind == Value::Kind::Number || value->kind == Value::Kind::Bool) return {value->number};
    std::vector<double> out;
    if (value->kind == Value::Kind::Array)
        for (const Value& item : value->items)
            if (item.kind == Value::Kind::Number || item.kind == Value::Kind::Bool) out.push_back(item.number);
    return out;
}

// A GLSL identifier (a NAME the host declares as a uniform).
bool identifier(const std::string& name) {
    if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

// The entries of an INPUTS (or CONTROLS) array that have a NAME and a TYPE.
std::vector<IsfInput> readInputs(const Value& inputs) {
    std::vector<IsfInput> out;
    for (const Value& item : inputs.items) {
        const Value* name = member(item, "NAME");
        const Value* type = member(item, "TYPE");
        if (!name || !type || name->kind != Value::Kind::String || type->kind != Value::Kind::String || !identifier(name->string))
            continue;
        IsfInput input;
        input.name = name->string, input.type = type->string;
        input.nameOffset = name->offset;
        if (const Value* label = member(item, "LABEL"); label && label->kind == Value::Kind::String) input.label = label->string;
        if (const Value* value = member(item, "DEFAULT")) {
            input.value = numbers(value);
            input.valueOffset = value->offset, input.valueLength = value->length;
        }
        input.low = numbers(member(item, "MIN")), input.high = numbers(member(item, "MAX"));
        if (const std::vector<double> values = numbers(member(item, "VALUES")); !values.empty() && input.low.empty()) {
            double least = values.front(), most = values.front();
            for (double v : values) least = std::min(least, v), most = std::max(most, v);
            input.low = {least}, input.high = {most};
        }
        out.push_back(std::move(input));
    }
    return out;
}

} // namespace

IsfHeader readIsfHeader(const std::string& text) {
    IsfHeader header;
    std::size_t at = 0;
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    if (text.compare(at, 2, "/*") != 0) return header;
    const std::size_t close = text.find("*/", at + 2);
    if (close == std::string::npos) return header;
    std::size_t open = at + 2;
    while (open < close && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
    if (open >= close || text[open] != '{') return header;
    Value root;
    if (!Reader(text, open, close).value(root) || root.kind != Value::Kind::Object) return header;
    const Value* inputs = member(root, "INPUTS");
    if (!inputs && !member(root, "ISFVSN")) return header;
    header.found = true;
    header.end = close + 2;
    if (!inputs || inputs->kind != Value::Kind::Array) return header;
    header.inputs = readInputs(*inputs);
    return header;
}

std::vector<IsfInput> readSceneControls(const std::string& json) {
    const std::size_t open = json.find('{');
    Value root;
    if (open == std::string::npos || !Reader(json, open, json.size()).value(root) || root.kind != Value::Kind::Object) return {};
    const Value* controls = member(root, "CONTROLS");
    return controls && controls->kind == Value::Kind::Array ? readInputs(*controls) : std::vector<IsfInput>{};
}

} // namespace sdfwb::shaders::detail
