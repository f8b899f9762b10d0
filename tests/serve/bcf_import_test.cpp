// BCF import (mtcs/serve/bcf_import.h): buildingSMART's official BCF 3.0 test cases read with
// what they say, a file exported here read back to the same items, and hostile zips refused
// before anything is kept (names that climb out of the folder, bombs, floods of entries).
#include <catch2/catch.hpp>
#include <unistd.h>
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mtcs/serve/bcf_export.h"
#include "mtcs/serve/bcf_import.h"
#include "mtcs/serve/review_store.h"
#include "support/paths.h"

namespace fs = std::filesystem;
using mtcs::serve::BcfError;
using mtcs::serve::BcfLimits;
using mtcs::serve::BcfTopic;
using mtcs::serve::read_bcf;
using nlohmann::json;

namespace {

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string test_case(const std::string& name) {
  return bytes_of(fs::path(mtcs_test::source_dir()) / "tests/data/bcf/test_cases" / (name + ".bcf"));
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mtcs_bcf_import_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// A zip of the given entries (name, content), written by libzip (stored or deflated).
std::string zip_of(const std::vector<std::pair<std::string, std::string>>& entries, bool deflate = true) {
  const fs::path path = scratch("made.zip");
  fs::remove(path);
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_EXCL, &error);
  REQUIRE(z);
  for (const auto& [name, text] : entries) {
    zip_source_t* s = zip_source_buffer(z, text.data(), text.size(), 0);
    const zip_int64_t i = zip_file_add(z, name.c_str(), s, ZIP_FL_ENC_UTF_8);
    REQUIRE(i >= 0);
    zip_set_file_compression(z, zip_uint64_t(i), deflate ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 9);
  }
  REQUIRE(zip_close(z) == 0);
  return bytes_of(path);
}

const std::string kVersion = R"(<?xml version="1.0"?><Version VersionId="3.0"/>)";

std::string markup(const std::string& guid, const std::string& extra = "") {
  return R"(<?xml version="1.0"?><Markup><Topic Guid=")" + guid +
         R"(" TopicType="Issue" TopicStatus="Open"><Title>t</Title><CreationDate>2024-01-02T03:04:05Z</CreationDate>)"
         "<CreationAuthor>a@b</CreationAuthor>" + extra + "</Topic></Markup>";
}

std::string error_of(const std::string& bytes, const BcfLimits& limits = {}) {
  try {
    read_bcf(bytes, limits);
  } catch (const BcfError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("bcf import: every official BCF 3.0 test case reads, with what it says", "[serve][bcf]") {
  for (const auto& entry : fs::directory_iterator(fs::path(mtcs_test::source_dir()) / "tests/data/bcf/test_cases")) {
    INFO(entry.path().filename());
    const auto topics = read_bcf(bytes_of(entry.path()));
    CHECK_FALSE(topics.empty());
    for (const BcfTopic& t : topics) {
      CHECK(t.guid.size() == 36);
      CHECK_FALSE(t.title.empty());
      CHECK(t.created > 1.4e9);  // 2014 or later
      for (const auto& c : t.comments) CHECK((c.viewpoint.empty() || t.viewpoints.count(c.viewpoint) == 1));
    }
  }
  const auto labels = read_bcf(test_case("Labels"));
  REQUIRE(labels.size() == 1);
  const BcfTopic& t = labels[0];
  CHECK(t.guid == "bee19eb8-3ec0-4e0d-90df-52afc806beaf");
  CHECK(t.title == "Labels");
  CHECK(t.status == "Open");
  CHECK(t.type == "Error");
  CHECK(t.labels == std::vector<std::string>{"Architects"});
  CHECK(t.author == "Architect@example.com");
  CHECK(t.created == Approx(1613552897.927));  // 2021-02-17T09:08:17.927Z
  REQUIRE(t.comments.size() == 1);
  CHECK(t.comments[0].text == "Here is a viewpoint also");
  CHECK(t.comments[0].viewpoint == "064ad3a0-f778-4b7a-b928-614ab5e27d90");
  const json& camera = t.viewpoints.at("064ad3a0-f778-4b7a-b928-614ab5e27d90");
  CHECK(camera["camera_view_point"][0].get<double>() == Approx(21973.04764116843));  // metres -> mm
  CHECK(camera["camera_direction"][2].get<double>() == Approx(-0.5773502691896255));
  CHECK(camera["field_of_view"].get<double>() == 60);

  const auto due = read_bcf(test_case("DueDate"));
  REQUIRE(due.size() == 1);
  CHECK(due[0].due == Approx(1615806000));  // 2021-03-15T11:00:00.000Z
  CHECK(due[0].assignee == "Architect@example.com");
  CHECK(read_bcf(test_case("Related_topics_with_both_topics_in_the_same_file")).size() == 2);
  CHECK(read_bcf(test_case("Minimum_information"))[0].comments.empty());
}

TEST_CASE("bcf import: a file exported here reads back to the same items", "[serve][bcf]") {
  const json view{{"camera_view_point", {10.5, -20.25, 300}}, {"camera_direction", {0, 0.6, -0.8}},
                  {"camera_up_vector", {0, 0.8, 0.6}},       {"field_of_view", 50},
                  {"aspect_ratio", 1.25}};
  const json topics = json::array(
      {{{"id", 3}, {"title", "gear teeth through the cup"}, {"status", "in_progress"}, {"assignee", "ana"},
        {"finding", "k1"}, {"created_by", "bo"}, {"created", 1.7e9}, {"modified", 1.7e9 + 60}, {"labels", {"core"}},
        {"due", 1.7e9 + 86400},
        {"comments", {{{"id", 7}, {"text", "see here"}, {"author", "bo"}, {"created", 1.7e9 + 1}, {"viewpoint", view}},
                      {{"id", 8}, {"text", "fixed"}, {"author", "ana"}, {"created", 1.7e9 + 2}, {"viewpoint", nullptr}}}}}});
  const std::string file = mtcs::serve::bcf_archive(4, topics, scratch("").string());
  const auto back = read_bcf(file);
  REQUIRE(back.size() == 1);
  const BcfTopic& t = back[0];
  CHECK(t.guid == mtcs::serve::derived_guid("topic|4|3"));
  CHECK(t.title == "gear teeth through the cup");
  CHECK(t.status == "IN_PROGRESS");
  CHECK(t.assignee == "ana");
  CHECK(t.author == "bo");
  CHECK(t.labels == std::vector<std::string>{"core"});
  CHECK(t.created == 1.7e9);
  CHECK(t.due == 1.7e9 + 86400);
  REQUIRE(t.comments.size() == 2);
  CHECK(t.comments[0].text == "see here");
  CHECK(t.comments[1].viewpoint.empty());
  const json& camera = t.viewpoints.at(t.comments[0].viewpoint);
  for (int i = 0; i < 3; ++i) {
    CHECK(camera["camera_view_point"][i].get<double>() == Approx(view["camera_view_point"][i].get<double>()).epsilon(1e-12));
    CHECK(camera["camera_up_vector"][i].get<double>() == Approx(view["camera_up_vector"][i].get<double>()).margin(1e-15));
  }
  CHECK(camera["aspect_ratio"].get<double>() == 1.25);
}

TEST_CASE("bcf import: hostile and broken files are refused, naming the entry", "[serve][bcf]") {
  const std::string guid = "01234567-89ab-4cde-8f01-23456789abcd";
  CHECK_THAT(error_of("PK\x03\x04 not really"), Catch::Contains("not a BCF file (a zip)"));
  CHECK_THAT(error_of(""), Catch::Contains("no bcf.version"));  // libzip reads no bytes as an empty zip
  CHECK_THAT(error_of(zip_of({{guid + "/markup.bcf", markup(guid)}})), Catch::Contains("no bcf.version"));
  CHECK_THAT(error_of(zip_of({{"bcf.version", R"(<Version VersionId="2.1"/>)"}})), Catch::Contains("knows BCF 3.0"));
  // Names that climb out of the folder a careless reader would unpack into (zip-slip).
  for (const std::string bad : {"../evil.bcf", "/etc/passwd", "a/../../b", "c:\\x", "a\\b", "a//b"}) {
    INFO(bad);
    CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {bad, "x"}})), Catch::Contains("a name no BCF file has"));
  }
  // A viewpoint file named outside the topic's folder.
  const std::string view = "11111111-2222-4333-8444-555555555555";
  const std::string climbing =
      markup(guid, R"(<Viewpoints><ViewPoint Guid=")" + view + R"("><Viewpoint>../x.bcfv</Viewpoint></ViewPoint></Viewpoints>)");
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", climbing}})),
             Catch::Contains("names no file of its folder"));
  // A bomb: 6 MB of spaces in a markup compress ~1000-fold.
  const std::string bomb = markup(guid) + std::string(6u << 20, ' ');
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", bomb}})), Catch::Contains("zip bomb"));
  BcfLimits small;
  small.max_entry_bytes = 1000;
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", markup(guid) + std::string(2000, ' ')}}, false), small),
             Catch::Contains("expands past 1000 bytes"));
  small = {};
  small.max_total_bytes = 200;
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", markup(guid)}}, false), small),
             Catch::Contains("the zip expands past 200 bytes"));
  small = {};
  small.max_entries = 10;
  std::vector<std::pair<std::string, std::string>> many{{"bcf.version", kVersion}};
  for (int i = 0; i < 11; ++i) many.emplace_back("f" + std::to_string(i), "");
  CHECK_THAT(error_of(zip_of(many), small), Catch::Contains("more than 10"));
  // Broken markup, named by entry and field.
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", "<Markup><Topic"}})),
             Catch::Contains(guid + "/markup.bcf': not XML"));
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", markup(guid, "<DueDate>soon</DueDate>")}})),
             Catch::Contains("DueDate: not a date and time"));
  const std::string dangling = markup(guid, R"(<Comments><Comment Guid=")" + view +
                                                R"("><Date>2024-01-02T03:04:05Z</Date><Author>a</Author><Comment>x</Comment><Viewpoint Guid=")" +
                                                view + R"("/></Comment></Comments>)");
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", dangling}})),
             Catch::Contains("which the topic does not list"));
  // What would break the store, a JSON answer or the next export: a GUID that is not one (it names
  // the exported folder), text that is not UTF-8, a camera number past double's range once in mm.
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", markup("../../x")}})),
             Catch::Contains("Topic Guid '../../x' is not a GUID"));
  std::string bad_text = markup(guid);
  bad_text.replace(bad_text.find("<Title>t"), 8, "<Title>\xC0\xAF");  // an overlong '/'
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", bad_text}})),
             Catch::Contains("Title is not UTF-8"));
  std::string surrogate = markup(guid);
  surrogate.replace(surrogate.find("<Title>t"), 8, "<Title>&#xD800;");
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", surrogate}})),
             Catch::Contains("Title is not UTF-8"));
  const std::string far_view =
      markup(guid, R"(<Viewpoints><ViewPoint Guid=")" + view + R"("><Viewpoint>v.bcfv</Viewpoint></ViewPoint></Viewpoints>)");
  const std::string far_camera =
      "<VisualizationInfo><PerspectiveCamera><CameraViewPoint><X>1e306</X><Y>0</Y><Z>0</Z></CameraViewPoint>"
      "<CameraDirection><X>0</X><Y>0</Y><Z>-1</Z></CameraDirection><CameraUpVector><X>0</X><Y>1</Y><Z>0</Z>"
      "</CameraUpVector><FieldOfView>60</FieldOfView></PerspectiveCamera></VisualizationInfo>";
  CHECK_THAT(error_of(zip_of({{"bcf.version", kVersion}, {guid + "/markup.bcf", far_view}, {guid + "/v.bcfv", far_camera}})),
             Catch::Contains("X is not a number of at most 1e9"));
}

TEST_CASE("bcf import: dates with a zone, an offset or none are UTC seconds", "[serve][bcf]") {
  CHECK(mtcs::serve::bcf_time("1970-01-01T00:00:00Z") == 0);
  CHECK(mtcs::serve::bcf_time("2021-03-15T11:00:00.000Z") == 1615806000);
  CHECK(mtcs::serve::bcf_time("2021-03-15T12:30:00+01:30") == 1615806000);
  CHECK(mtcs::serve::bcf_time("2021-03-15T11:00:00") == 1615806000);
  CHECK(mtcs::serve::bcf_time(" 2021-03-15T11:00:00Z\n") == 1615806000);  // xs:dateTime's whitespace
  CHECK(mtcs::serve::bcf_time("2024-02-29T00:00:00.5Z") == 1709164800.5);
  for (const char* bad : {"2021-13-15T11:00:00Z", "2021-03-15T11:00:00 CET", "2021-02-31T00:00:00Z", "2023-02-29T00:00:00Z",
                          "2021-03-15T-1:-5:00Z", "2021-03-15T11:00:00+ab:cd", "2021-03-15T11:00:00+99:00", "", "2021"}) {
    INFO(bad);
    CHECK_THROWS_AS(mtcs::serve::bcf_time(bad), BcfError);
  }
}

TEST_CASE("bcf import: into a project once, again adds nothing, and its own export adds nothing", "[serve][bcf]") {
  const fs::path db = scratch("store.sqlite");
  fs::remove(db);
  mtcs::serve::ReviewStore store(db);
  const long owner = store.add_user("ana", "x", mtcs::serve::Role::owner);
  const long project = store.add_project("mold", owner);
  const auto topics = read_bcf(test_case("Labels"));
  const json first = store.import_topics(project, topics, owner);
  CHECK(first["topics_added"] == 1);
  CHECK(first["comments_added"] == 1);
  const json again = store.import_topics(project, topics, owner);
  CHECK(again["topics_added"] == 0);
  CHECK(again["topics_updated"] == 1);
  CHECK(again["comments_added"] == 0);
  const json items = store.topics(project, mtcs::serve::Role::owner);
  REQUIRE(items.size() == 1);
  CHECK(items[0]["guid"] == "bee19eb8-3ec0-4e0d-90df-52afc806beaf");
  CHECK(items[0]["created_by"] == "ana");  // the importer's account, never one the file names
  CHECK(items[0]["bcf_author"] == "Architect@example.com");
  CHECK(items[0]["labels"] == json::array({"Architects"}));
  CHECK(items[0]["status"] == "open");
  CHECK(items[0]["comments"][0]["author"] == "ana");
  CHECK(items[0]["comments"][0]["bcf_author"] == "Architect@example.com");
  CHECK(items[0]["comments"][0]["viewpoint"]["field_of_view"] == 60);
  // An item made here, exported and read back: known by its derived GUID.
  const long own = store.add_topic(project, "made here", "", owner);
  store.add_comment(project, own, "first", nullptr, owner);
  const std::string file = mtcs::serve::bcf_archive(project, store.topics(project, mtcs::serve::Role::owner), scratch("").string());
  const json round = store.import_topics(project, read_bcf(file), owner);
  CHECK(round["topics_added"] == 0);
  CHECK(round["comments_added"] == 0);
  CHECK(store.topics(project, mtcs::serve::Role::owner).size() == 2);
}
