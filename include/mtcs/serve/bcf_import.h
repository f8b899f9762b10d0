#pragma once
// A BCF-XML 3.0 file (buildingSMART's BIM Collaboration Format) read into review items: each
// topic's GUID, type, status, title, description, labels, dates, authors, assignee, due date,
// comments, and the perspective cameras of its viewpoints (metres in the file, millimetres here,
// as the meshes). The zip is read from memory and trusted in nothing: its entry names (no
// absolute paths, no "..", no backslashes), its entry count, each entry's size and compression
// ratio, and the whole size it expands to are bounded before anything is kept. What it cannot
// read is a BcfError naming the entry and the field.

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace mtcs::serve {

struct BcfError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BcfLimits {
  std::size_t max_entries = 4096;                  // files and folders in the zip
  std::uint64_t max_entry_bytes = 8ull << 20;      // one markup or viewpoint, expanded
  std::uint64_t max_total_bytes = 64ull << 20;     // every entry read, expanded
  double max_ratio = 200;                          // expanded / compressed, past 1 MiB (a zip bomb)
};

struct BcfComment {
  std::string guid, author, text, viewpoint;  // viewpoint: a GUID of the topic's viewpoints, or ""
  double date = 0;                            // seconds since 1970 (UTC)
};

struct BcfTopic {
  std::string guid, type, status, title, description, author, assignee;
  std::vector<std::string> labels;
  double created = 0, modified = 0, due = 0;  // 0: not given
  std::vector<BcfComment> comments;
  // viewpoint GUID -> {camera_view_point (mm), camera_direction, camera_up_vector, field_of_view
  // (degrees), aspect_ratio}, as the review app and bcf_archive keep them; null when the viewpoint
  // has no perspective camera (an orthogonal one, or none).
  std::map<std::string, nlohmann::json> viewpoints;
};

// The topics of a .bcf file's bytes, in the order of their folders.
std::vector<BcfTopic> read_bcf(std::string_view zip_bytes, const BcfLimits& limits = {});

// "2021-02-17T09:08:17.927Z" (xs:dateTime, with Z, an offset or none: UTC) in seconds since 1970.
double bcf_time(const std::string& text);

}  // namespace mtcs::serve
