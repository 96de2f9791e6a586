// Failures that name request keys know where they name them, so each front end words them its
// own way (core/KeyedText.h): the text stays the request's, and the words come from the caller.
#include <jobs/Jobs.h>
#include <jobs/Protocol.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace sdfwb;

namespace {

// The command line's words for a few keys, as a front end would give them.
std::string optionTerm(const std::string& path) {
    if (path == "width" || path == "height") return "--size";
    if (path == "n") return "-n";
    std::string option = "--" + std::string(keyName(path));
    for (char& c : option)
        if (c == '_') c = '-';
    return option;
}

std::vector<std::string> paths(const std::vector<KeyMention>& keys) {
    std::vector<std::string> out;
    for (const KeyMention& k : keys) out.push_back(k.path);
    return out;
}

} // namespace

TEST(KeyedText, KeepsWhereEachKeyIsWrittenThroughConcatenation) {
    const KeyedText text = "sample: " + keys({"width", "height"}) + ": got 0x0, see " + key("trace.max_steps");
    EXPECT_EQ(text.text(), "sample: 'width', 'height': got 0x0, see 'max_steps'");
    ASSERT_EQ(text.keys().size(), 3u);
    EXPECT_EQ(text.text().substr(text.keys()[0].offset, text.keys()[0].length), "'width'");
    EXPECT_EQ(text.text().substr(text.keys()[2].offset, text.keys()[2].length), "'max_steps'");
    EXPECT_EQ(paths(text.keys()), (std::vector<std::string>{"width", "height", "trace.max_steps"}));
}

TEST(KeyedText, AFrontEndWordsOnlyTheKeysAndNamesTwoKeysOfOneOptionOnce) {
    const KeyedText text = keys({"width", "height"}) + ": '" + std::string("width") + "' is " + key("n") + " / " + key("fov");
    // The user's own text ('width' here) is not a key: only the recorded places change.
    EXPECT_EQ(worded(text.text(), text.keys(), optionTerm), "--size: 'width' is -n / --fov");
    // Without a front end's words the text is the request's.
    EXPECT_EQ(text.text(), "'width', 'height': 'width' is 'n' / 'fov'");
    // Two keys worded alike but not side by side are both named.
    const KeyedText apart = key("width") + " and " + key("height");
    EXPECT_EQ(worded(apart.text(), apart.keys(), optionTerm), "--size and --size");
}

TEST(KeyedText, ALowerLayersKeyThenColonBecomesAKey) {
    const KeyedText keyed = keyedSubject("sign: expected winding, parity or pseudonormal");
    EXPECT_EQ(keyed.text(), "'sign': expected winding, parity or pseudonormal");
    EXPECT_EQ(paths(keyed.keys()), std::vector<std::string>{"sign"});
    for (const char* plain : {"Sphere.glsl: no such file", "no colon here", ": starts with one"}) {
        EXPECT_EQ(keyedSubject(plain).text(), plain);
        EXPECT_TRUE(keyedSubject(plain).keys().empty()) << plain;
    }
}

TEST(KeyedText, ErrorsCarryTheirKeysThroughExpectedAndIntoAJobError) {
    const Expected<int> failed = makeError("eval: " + key("tau") + " must be positive");
    EXPECT_EQ(failed.error().message, "eval: 'tau' must be positive");
    const jobs::JobError error = jobs::usageError(failed.error().keyed());
    EXPECT_EQ(error.failure, jobs::Failure::Usage);
    EXPECT_EQ(worded(error.message, error.keys, optionTerm), "eval: --tau must be positive");
}

// The validators name the key paths of the request as its JSON nests them.
TEST(KeyedText, ValidationNamesTheKeyPathsAtFault) {
    values::SampleRequest sample;
    sample.sdf.sdf = "sphere";
    sample.pattern = "near";
    sample.count = 10;
    sample.nearTruncation = 2.0f;
    auto error = jobs::validate(sample);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message, "'near_truncation': needs 'near_widths'");
    EXPECT_EQ(paths(error->keys), (std::vector<std::string>{"near_truncation", "near_widths"}));

    values::RenderRequest render;
    render.frame.sdf.sdf = "sphere";
    render.output = "out.png";
    render.frame.camera.fovYDegrees = 200.0f;
    error = jobs::validate(render);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message, "'fov': must be 1..179, got 200");
    EXPECT_EQ(paths(error->keys), std::vector<std::string>{"camera.fov"});
    EXPECT_EQ(worded(error->message, error->keys, optionTerm), "--fov: must be 1..179, got 200");
}

// The worker protocol carries where the message names keys, so the workbench words them too.
TEST(KeyedText, TheWorkerProtocolCarriesTheKeys) {
    const jobs::JobError sent = jobs::usageError(keys({"width", "height"}) + ": got 0x0 for " + key("trace.max_steps"));
    const jobs::JobError read = jobs::readWorkerMessage(jobs::errorMessage(sent)).error;
    EXPECT_EQ(read.failure, jobs::Failure::Usage);
    EXPECT_EQ(read.message, sent.message);
    EXPECT_EQ(paths(read.keys), paths(sent.keys));
    EXPECT_EQ(worded(read.message, read.keys, optionTerm), "--size: got 0x0 for --max-steps");
    // A mention that no longer points at its key's quoted name is left as the text has it.
    jobs::JobError moved = sent;
    moved.keys[2].offset += 1;
    EXPECT_EQ(worded(moved.message, moved.keys, optionTerm), "--size: got 0x0 for 'max_steps'");
    // A message that names no key is sent as before, without "keys".
    EXPECT_EQ(jobs::errorMessage(jobs::workError("plain")).find("keys"), std::string::npos);
}
