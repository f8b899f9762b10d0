#include "mtcs/serve/bcf_export.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "mtcs/serve/credentials.h"

namespace mtcs::serve {
namespace {

using nlohmann::json;
constexpr double kMetresPerMillimetre = 0.001;

std::string iso_time(double seconds) {
  const std::time_t t = std::time_t(seconds);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string bcf_status(const std::string& status) {
  std::string out;
  for (char c : status) out += char(std::toupper(static_cast<unsigned char>(c)));
  return out;  // open -> OPEN, in_progress -> IN_PROGRESS, ...
}

std::string xml_text(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

pugi::xml_node root(pugi::xml_document& doc, const char* name, const char* schema) {
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto r = doc.append_child(name);
  r.append_attribute("xmlns:xsi") = "http://www.w3.org/2001/XMLSchema-instance";
  r.append_attribute("xsi:noNamespaceSchemaLocation") = schema;
  return r;
}

void xyz(pugi::xml_node parent, const char* name, const json& v, double scale) {
  auto n = parent.append_child(name);
  const char* axes[] = {"X", "Y", "Z"};
  for (int i = 0; i < 3; ++i) n.append_child(axes[i]).text() = v.at(i).get<double>() * scale;
}

std::string viewpoint_file(const std::string& guid, const json& v) {
  pugi::xml_document doc;
  auto info = root(doc, "VisualizationInfo", "visinfo.xsd");
  info.append_attribute("Guid") = guid.c_str();
  auto camera = info.append_child("PerspectiveCamera");
  xyz(camera, "CameraViewPoint", v.at("camera_view_point"), kMetresPerMillimetre);
  json direction = v.at("camera_direction"), up = v.at("camera_up_vector");
  xyz(camera, "CameraDirection", direction, 1);
  xyz(camera, "CameraUpVector", up, 1);
  camera.append_child("FieldOfView").text() = v.value("field_of_view", 45.0);
  camera.append_child("AspectRatio").text() = v.value("aspect_ratio", 1.5);
  return xml_text(doc);
}

std::string markup_file(long project, const json& topic, const std::string& guid,
                        std::vector<std::pair<std::string, std::string>>& viewpoints) {
  pugi::xml_document doc;
  auto markup = root(doc, "Markup", "markup.xsd");
  auto t = markup.append_child("Topic");
  t.append_attribute("Guid") = guid.c_str();
  t.append_attribute("ServerAssignedId") = ("MTCS-" + std::to_string(topic.at("id").get<long>())).c_str();
  t.append_attribute("TopicType") = topic.value("finding", "").empty() ? "ISSUE" : "CLASH";
  t.append_attribute("TopicStatus") = bcf_status(topic.at("status")).c_str();
  t.append_child("Title").text() = topic.at("title").get<std::string>().c_str();
  if (const json labels = topic.value("labels", json::array()); !labels.empty()) {
    auto l = t.append_child("Labels");
    for (const json& label : labels)
      if (!label.get<std::string>().empty()) l.append_child("Label").text() = label.get<std::string>().c_str();
  }
  t.append_child("CreationDate").text() = iso_time(topic.at("created")).c_str();
  // An imported item keeps the author its file named.
  const std::string named = topic.value("bcf_author", "");
  t.append_child("CreationAuthor").text() = (named.empty() ? topic.at("created_by").get<std::string>() : named).c_str();
  t.append_child("ModifiedDate").text() = iso_time(topic.at("modified")).c_str();
  if (const double due = topic.value("due", 0.0); due > 0) t.append_child("DueDate").text() = iso_time(due).c_str();
  if (const std::string who = topic.value("assignee", ""); !who.empty()) t.append_child("AssignedTo").text() = who.c_str();
  if (const std::string text = topic.value("description", ""); !text.empty())
    t.append_child("Description").text() = text.c_str();
  else if (const std::string key = topic.value("finding", ""); !key.empty())
    t.append_child("Description").text() = ("mtcs finding " + key).c_str();
  auto comments = t.append_child("Comments");
  for (const json& c : topic.at("comments")) {
    const std::string kept = c.value("guid", "");
    const std::string this_comment =
        kept.empty() ? comment_guid(project, c.at("id").get<long>()) : kept;
    auto node = comments.append_child("Comment");
    node.append_attribute("Guid") = this_comment.c_str();
    node.append_child("Date").text() = iso_time(c.at("created")).c_str();
    const std::string by = c.value("bcf_author", "");
    node.append_child("Author").text() = (by.empty() ? c.at("author").get<std::string>() : by).c_str();
    if (const std::string text = c.at("text"); !text.empty()) node.append_child("Comment").text() = text.c_str();
    if (c.contains("viewpoint") && c["viewpoint"].is_object() && c["viewpoint"].contains("camera_view_point")) {
      const std::string view_guid = derived_guid("viewpoint|" + this_comment);
      node.append_child("Viewpoint").append_attribute("Guid") = view_guid.c_str();
      viewpoints.emplace_back(view_guid, viewpoint_file(view_guid, c["viewpoint"]));
    }
  }
  // The schema orders Comments before Viewpoints: the list is written after the comments.
  if (!viewpoints.empty()) {
    auto views = t.append_child("Viewpoints");
    for (const auto& [view_guid, text] : viewpoints) {
      auto v = views.append_child("ViewPoint");
      v.append_attribute("Guid") = view_guid.c_str();
      v.append_child("Viewpoint").text() = (view_guid + ".bcfv").c_str();
    }
  }
  return xml_text(doc);
}

std::string extensions_file(const json& topics) {
  pugi::xml_document doc;
  auto ext = root(doc, "Extensions", "extensions.xsd");
  auto types = ext.append_child("TopicTypes");
  for (const char* type : {"CLASH", "ISSUE"}) types.append_child("TopicType").text() = type;
  auto statuses = ext.append_child("TopicStatuses");
  for (const char* s : {"OPEN", "IN_PROGRESS", "RESOLVED", "CLOSED"}) statuses.append_child("TopicStatus").text() = s;
  std::vector<std::string> users;
  for (const json& t : topics) {
    users.push_back(t.at("created_by"));
    for (const json& c : t.at("comments")) users.push_back(c.at("author"));
    if (const std::string who = t.value("assignee", ""); !who.empty()) users.push_back(who);
  }
  std::sort(users.begin(), users.end());
  users.erase(std::unique(users.begin(), users.end()), users.end());
  auto u = ext.append_child("Users");
  for (const auto& name : users) u.append_child("User").text() = name.c_str();
  return xml_text(doc);
}

// The files into a zip: libzip writes to a file, read back whole.
std::string zipped(const std::vector<std::pair<std::string, std::string>>& files, const std::string& scratch) {
  const std::string path = scratch + "/" + random_token() + ".bcf";
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_EXCL, &error);
  if (!z) throw std::runtime_error("BCF export: cannot create " + path);
  for (const auto& [name, text] : files) {
    zip_source_t* source = zip_source_buffer(z, text.data(), text.size(), 0);
    if (!source || zip_file_add(z, name.c_str(), source, ZIP_FL_ENC_UTF_8) < 0) {
      if (source) zip_source_free(source);
      zip_discard(z);
      throw std::runtime_error("BCF export: cannot add " + name);
    }
  }
  if (zip_close(z) != 0) {
    zip_discard(z);
    throw std::runtime_error("BCF export: cannot write the zip");
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path.c_str());
  return bytes;
}

}  // namespace

std::string derived_guid(const std::string& text) {
  Sha256 h;
  h.add(text.data(), text.size());
  std::string hex = h.hex().substr(0, 32);
  hex[12] = '4';                                          // version 4
  hex[16] = "89ab"[std::stoi(hex.substr(16, 1), nullptr, 16) & 3];  // variant 10xx
  return hex.substr(0, 8) + "-" + hex.substr(8, 4) + "-" + hex.substr(12, 4) + "-" + hex.substr(16, 4) + "-" +
         hex.substr(20, 12);
}

std::string topic_guid(long project, long topic) {
  return derived_guid("topic|" + std::to_string(project) + "|" + std::to_string(topic));
}

std::string comment_guid(long project, long comment) {
  return derived_guid("comment|" + std::to_string(project) + "|" + std::to_string(comment));
}

std::string bcf_archive(long project, const json& topics, const std::string& scratch) {
  std::vector<std::pair<std::string, std::string>> files;
  {
    pugi::xml_document doc;
    root(doc, "Version", "version.xsd").append_attribute("VersionId") = "3.0";
    files.emplace_back("bcf.version", xml_text(doc));
  }
  files.emplace_back("extensions.xml", extensions_file(topics));
  for (const json& topic : topics) {
    const std::string kept = topic.value("guid", "");  // an item read from a BCF file keeps its GUID
    const std::string guid =
        kept.empty() ? topic_guid(project, topic.at("id").get<long>()) : kept;
    std::vector<std::pair<std::string, std::string>> viewpoints;
    files.emplace_back(guid + "/markup.bcf", markup_file(project, topic, guid, viewpoints));
    for (const auto& [view_guid, text] : viewpoints) files.emplace_back(guid + "/" + view_guid + ".bcfv", text);
  }
  return zipped(files, scratch);
}

}  // namespace mtcs::serve
