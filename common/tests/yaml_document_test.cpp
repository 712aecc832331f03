// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The compact YAML document and its node view: what the loaders rely on (lookups, iteration, marks, nulls),
// aliases as references (a "billion laughs" input stays as small as its text), and duplicate keys rejected with
// their position in small maps (scanned) and big ones (hashed).
#define BOOST_TEST_MODULE yaml_document
#include <boost/test/unit_test.hpp>

#include <stipple/yaml/strict_yaml.h>

#include <string>
#include <vector>

using namespace stipple::yaml;

namespace {

Node parse(const std::string& text) { return StrictYaml("t.yaml").parse(text); }

std::string parseError(const std::string& text) {
    try {
        parse(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "(parsed)";
}

} // namespace

BOOST_AUTO_TEST_CASE(lookups_iteration_and_marks) {
    const Node root = parse("name: box\nlist: [1, two, [3]]\nempty:\ntilde: ~\nmap: {a: 1, b: 2}\n");
    BOOST_TEST(root.IsMap());
    BOOST_TEST(root.size() == 5u);
    BOOST_TEST(root["name"].Scalar() == "box");
    BOOST_TEST(!root["missing"]);
    BOOST_TEST(!root["missing"].IsDefined());
    BOOST_TEST(root["empty"].IsDefined());
    BOOST_TEST(root["empty"].IsNull());
    BOOST_TEST(root["tilde"].IsNull());
    const Node list = root["list"];
    BOOST_TEST(list.IsSequence());
    BOOST_TEST(list.size() == 3u);
    BOOST_TEST(list[1].Scalar() == "two");
    BOOST_TEST(list[2].IsSequence());
    BOOST_TEST(!list[3]);
    BOOST_TEST(list["a"].IsDefined() == false);
    std::vector<std::string> items;
    for (const Node& item : list) items.push_back(item.IsScalar() ? item.Scalar() : "seq");
    BOOST_TEST((items == std::vector<std::string>{"1", "two", "seq"}));
    std::string pairs;
    for (const auto& kv : root["map"]) pairs += kv.first.Scalar() + "=" + kv.second.Scalar() + ";";
    BOOST_TEST(pairs == "a=1;b=2;");
    BOOST_TEST(root["map"].begin()->first.Scalar() == "a");
    BOOST_TEST(StrictYaml("t.yaml").where(list[1]) == "t.yaml:2:11");
    BOOST_TEST(StrictYaml("t.yaml").where(root["missing"]) == "t.yaml");
    BOOST_TEST(list[0].Scalar() == "1");
    BOOST_TEST(root["list"].Scalar() == "");
}

BOOST_AUTO_TEST_CASE(empty_document_is_undefined) {
    BOOST_TEST(!parse(""));
    BOOST_TEST(!parse("# only a comment\n").IsMap());
}

BOOST_AUTO_TEST_CASE(numbers_are_whole_finite_scalars) {
    const Node root = parse("[1.5, 1.5x, inf, ' 2', 42, 99999999999999999999]");
    double v = 0;
    BOOST_TEST((StrictYaml::parseNumber(root[0], v) == StrictYaml::Number::Ok && v == 1.5));
    BOOST_TEST((StrictYaml::parseNumber(root[1], v) == StrictYaml::Number::NotANumber));
    BOOST_TEST((StrictYaml::parseNumber(root[2], v) == StrictYaml::Number::NotFinite));
    BOOST_TEST((StrictYaml::parseNumber(root[3], v) == StrictYaml::Number::NotANumber));
    long long i = 0;
    BOOST_TEST((StrictYaml::parseInteger(root[4], i) && i == 42));
    BOOST_TEST(!StrictYaml::parseInteger(root[5], i));
    BOOST_TEST(!StrictYaml::parseInteger(root, i));
}

BOOST_AUTO_TEST_CASE(aliases_are_references_not_copies) {
    const Node root = parse("a: &x [1, 2]\nb: *x\n");
    BOOST_TEST(root["b"].IsSequence());
    BOOST_TEST(root["b"][1].Scalar() == "2");
    BOOST_TEST(root["b"].Mark().line == root["a"].Mark().line);
    BOOST_TEST(root["b"].Mark().column == root["a"].Mark().column);

    // Nine levels of ten aliases: 10^9 leaves if copied, a few hundred bytes of text.
    std::string laughs = "l0: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
    for (int i = 1; i <= 9; ++i) {
        laughs += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
        for (int j = 0; j < 10; ++j) laughs.append(j ? ", *l" : "*l").append(std::to_string(i - 1));
        laughs += "]\n";
    }
    const auto doc = Document::parse(laughs);
    BOOST_TEST(doc->bytes() < 4u * laughs.size() + 256u * 1024u);
    const Node top(doc, doc->root());
    BOOST_TEST(top["l9"][9][9][9][9][9][9][9][9][9][9].Scalar() == "lol");
}

BOOST_AUTO_TEST_CASE(duplicate_keys_are_errors_with_their_position) {
    BOOST_TEST(parseError("a: 1\nb: 2\na: 3\n") == "t.yaml:3:1: duplicate key 'a'");
    BOOST_TEST(parseError("list:\n  - {x: 1, y: 2, x: 3}\n") == "t.yaml:2:18: duplicate key 'x'");
    // A big map: the keys are hashed once there are many.
    std::string big = "{";
    for (int i = 0; i < 100; ++i) big.append("k").append(std::to_string(i)).append(": 0, ");
    BOOST_TEST(parseError(big + "k100: 0}") == "(parsed)");
    BOOST_TEST(parseError(big + "k57: 0}").find("duplicate key 'k57'") != std::string::npos);
    BOOST_TEST(parseError(big + "k57: 0}").find("t.yaml:1:") == 0u);
    // An alias as a key counts by its text.
    BOOST_TEST(parseError("x: &k a\ny: {a: 1, *k : 2}\n").find("duplicate key 'a'") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(syntax_and_depth_errors_keep_their_messages) {
    BOOST_TEST(parseError("a: [1, 2\n").find("t.yaml:") == 0u);
    BOOST_TEST(parseError("a: [1, 2\n").find("YAML syntax error") != std::string::npos);
    BOOST_TEST(parseError(std::string(3000, '[')).find("YAML nested deeper than the parser's limit") !=
               std::string::npos);
}
