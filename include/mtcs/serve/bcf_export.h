#pragma once
// A project's review items as BCF-XML 3.0 (buildingSMART's BIM Collaboration Format), the zip
// other review tools read: bcf.version, extensions.xml (the types, statuses and users used), and
// per item a folder named by its GUID with markup.bcf (title, status, dates, authors, assignee,
// comments) and one .bcfv per comment that carries a viewpoint (a perspective camera, in metres:
// the meshes' millimetres / 1000; vertical field of view in degrees). GUIDs are derived from the
// project and the item (or comment) id, so every export of an item names it the same.

#include <string>

#include <nlohmann/json.hpp>

namespace mtcs::serve {

// topics: as ReviewStore::topics gives them. Returns the .bcf file's bytes; `scratch` is a folder
// for the zip while it is written.
std::string bcf_archive(long project, const nlohmann::json& topics, const std::string& scratch);

// A GUID (8-4-4-4-12 lowercase hex, version 4 and variant bits set) derived from a text.
std::string derived_guid(const std::string& text);

// The GUIDs an export gives an item and a comment made here (an imported one keeps its own).
std::string topic_guid(long project, long topic);
std::string comment_guid(long project, long comment);

}  // namespace mtcs::serve
