#include "mtcs/serve/bcf_import.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <pugixml.hpp>
#include <set>

namespace mtcs::serve {
namespace {

using nlohmann::json;
constexpr double kMillimetresPerMetre = 1000;

// An entry name a writer of files could be tricked by (zip-slip), or one no BCF tool writes.
bool safe_name(const std::string& name) {
  if (name.empty() || name.size() > 512 || name.front() == '/' || name.find('\\') != std::string::npos ||
      name.find(':') != std::string::npos || name.find('\0') != std::string::npos)
    return false;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, end - start);
    if (part == ".." || part == "." || (part.empty() && end != name.size())) return false;
    start = end + 1;
  }
  return true;
}

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct FileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

class Archive {
 public:
  Archive(std::string_view bytes, const BcfLimits& limits) : limits_(limits) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    if (!source) {
      const std::string why = zip_error_strerror(&error);
      zip_error_fini(&error);
      throw BcfError("not a zip: " + why);
    }
    zip_.reset(zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error));
    if (!zip_) {
      zip_source_free(source);
      const std::string why = zip_error_strerror(&error);
      zip_error_fini(&error);
      throw BcfError("not a BCF file (a zip): " + why);
    }
    const zip_int64_t n = zip_get_num_entries(zip_.get(), 0);
    if (n < 0 || std::uint64_t(n) > limits.max_entries)
      throw BcfError("the zip holds " + std::to_string(n) + " entries, more than " +
                     std::to_string(limits.max_entries));
    for (zip_int64_t i = 0; i < n; ++i) {
      zip_stat_t st;
      zip_stat_init(&st);
      if (zip_stat_index(zip_.get(), zip_uint64_t(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
        throw BcfError("entry " + std::to_string(i) + ": unreadable");
      const std::string name = st.name;
      if (!safe_name(name)) throw BcfError("entry '" + name + "': a name no BCF file has (an absolute path, '..' or '\\')");
      if (!names_.insert(name).second) throw BcfError("entry '" + name + "': twice in the zip");
    }
  }

  bool has(const std::string& name) const { return names_.count(name) > 0; }
  const std::set<std::string>& names() const { return names_; }

  // The entry expanded, read no further than the limits allow (the sizes in its header are the
  // writer's word, not a fact).
  std::string read(const std::string& name) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat(zip_.get(), name.c_str(), 0, &st) != 0) throw BcfError("entry '" + name + "': missing");
    std::unique_ptr<zip_file_t, FileCloser> f(zip_fopen(zip_.get(), name.c_str(), 0));
    if (!f) throw BcfError("entry '" + name + "': " + zip_strerror(zip_.get()));
    std::string out;
    char buffer[65536];
    for (;;) {
      const zip_int64_t got = zip_fread(f.get(), buffer, sizeof buffer);
      if (got < 0) throw BcfError("entry '" + name + "': " + zip_file_strerror(f.get()));
      if (got == 0) break;
      out.append(buffer, std::size_t(got));
      total_ += std::uint64_t(got);
      if (out.size() > limits_.max_entry_bytes)
        throw BcfError("entry '" + name + "': expands past " + std::to_string(limits_.max_entry_bytes) + " bytes");
      if (total_ > limits_.max_total_bytes)
        throw BcfError("the zip expands past " + std::to_string(limits_.max_total_bytes) + " bytes");
      if ((st.valid & ZIP_STAT_COMP_SIZE) && out.size() > (1u << 20) &&
          double(out.size()) > limits_.max_ratio * double(std::max<zip_uint64_t>(st.comp_size, 1)))
        throw BcfError("entry '" + name + "': expands over " + std::to_string(int(limits_.max_ratio)) +
                       " times its compressed size (a zip bomb)");
    }
    return out;
  }

 private:
  BcfLimits limits_;
  std::unique_ptr<zip_t, ZipCloser> zip_;
  std::set<std::string> names_;
  std::uint64_t total_ = 0;
};

pugi::xml_document parse_xml(const std::string& text, const std::string& entry) {
  pugi::xml_document doc;
  // No entity expansion beyond XML's five: pugixml never fetches or expands external entities.
  const pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) throw BcfError("entry '" + entry + "': not XML (" + r.description() + " at byte " + std::to_string(r.offset) + ")");
  return doc;
}

// Well-formed UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF): what the store and
// every JSON answer built from it can hold.
bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (n < 0 || i + std::size_t(n) >= s.size() + (n == 0 ? 1 : 0)) return false;
    std::uint32_t cp = n == 0 ? c : n == 1 ? (c & 0x1F) : n == 2 ? (c & 0x0F) : (c & 0x07);
    for (int k = 1; k <= n; ++k) {
      const auto d = static_cast<unsigned char>(s[i + std::size_t(k)]);
      if ((d >> 6) != 2) return false;
      cp = (cp << 6) | (d & 0x3F);
    }
    const std::uint32_t least[] = {0, 0x80, 0x800, 0x10000};
    if (cp < least[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += std::size_t(n) + 1;
  }
  return true;
}

// A text the file gives, checked: UTF-8, and no longer than a review item holds.
std::string checked(const char* text, const char* field, std::size_t max_bytes, const std::string& entry) {
  std::string s = text;
  if (s.size() > max_bytes)
    throw BcfError("entry '" + entry + "': " + field + " is longer than " + std::to_string(max_bytes) + " bytes");
  if (!valid_utf8(s)) throw BcfError("entry '" + entry + "': " + field + " is not UTF-8");
  return s;
}

constexpr std::size_t kShort = 1024, kLong = 65536;  // a title, a name, a label; a comment

std::string child_text(pugi::xml_node node, const char* name, const std::string& entry, std::size_t max_bytes = kShort) {
  return checked(node.child(name).text().as_string(), name, max_bytes, entry);
}

// A GUID as BCF's shared-types.xsd has it (8-4-4-4-12 hex), lowercased: it names the item's folder
// when the project is exported again.
std::string guid_of(pugi::xml_attribute a, const char* what, const std::string& entry, bool required = true) {
  std::string g = a.as_string();
  if (g.empty() && !required) return g;
  bool ok = g.size() == 36;
  for (std::size_t i = 0; ok && i < g.size(); ++i) {
    if (i == 8 || i == 13 || i == 18 || i == 23) ok = g[i] == '-';
    else ok = std::isxdigit(static_cast<unsigned char>(g[i])) != 0, g[i] = char(std::tolower(static_cast<unsigned char>(g[i])));
  }
  if (!ok)
    throw BcfError("entry '" + entry + "': " + what + " Guid '" + checked(a.as_string(), "Guid", kShort, entry) +
                   "' is not a GUID");
  return g;
}

double time_field(pugi::xml_node node, const char* name, const std::string& entry, bool required) {
  const std::string text = child_text(node, name, entry);
  if (text.empty()) {
    if (required) throw BcfError("entry '" + entry + "': " + node.name() + " has no " + name);
    return 0;
  }
  try {
    return bcf_time(text);
  } catch (const BcfError& e) {
    throw BcfError("entry '" + entry + "': " + name + ": " + e.what());
  }
}

// A number of a camera, scaled; within a kilometre's millionfold, so that every figure stays finite
// through the store and the next export.
double number(pugi::xml_node node, const char* name, const std::string& entry, double scale = 1) {
  const std::string text = child_text(node, name, entry);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end) * scale;
  if (text.empty() || *end != '\0' || !std::isfinite(v) || std::abs(v) > 1e9)
    throw BcfError("entry '" + entry + "': " + name + " is not a number of at most 1e9: '" + text + "'");
  return v;
}

json vector3(pugi::xml_node node, const char* name, double scale, const std::string& entry) {
  const pugi::xml_node v = node.child(name);
  if (!v) throw BcfError("entry '" + entry + "': the camera has no " + name);
  return json::array({number(v, "X", entry, scale), number(v, "Y", entry, scale), number(v, "Z", entry, scale)});
}

json camera(const std::string& text, const std::string& entry) {
  const pugi::xml_document doc = parse_xml(text, entry);
  const pugi::xml_node info = doc.child("VisualizationInfo");
  if (!info) throw BcfError("entry '" + entry + "': no VisualizationInfo");
  const pugi::xml_node c = info.child("PerspectiveCamera");
  if (!c) return nullptr;  // an orthogonal camera or none: the review app shows perspective only
  json v{{"camera_view_point", vector3(c, "CameraViewPoint", kMillimetresPerMetre, entry)},
         {"camera_direction", vector3(c, "CameraDirection", 1, entry)},
         {"camera_up_vector", vector3(c, "CameraUpVector", 1, entry)},
         {"field_of_view", number(c, "FieldOfView", entry)}};
  if (c.child("AspectRatio")) v["aspect_ratio"] = number(c, "AspectRatio", entry);
  return v;
}

BcfTopic topic_of(Archive& zip, const std::string& folder) {
  const std::string entry = folder + "/markup.bcf";
  const pugi::xml_document doc = parse_xml(zip.read(entry), entry);
  const pugi::xml_node t = doc.child("Markup").child("Topic");
  if (!t) throw BcfError("entry '" + entry + "': no Markup/Topic");
  BcfTopic topic;
  topic.guid = guid_of(t.attribute("Guid"), "Topic", entry);
  topic.type = checked(t.attribute("TopicType").as_string(), "TopicType", kShort, entry);
  topic.status = checked(t.attribute("TopicStatus").as_string(), "TopicStatus", kShort, entry);
  topic.title = child_text(t, "Title", entry);
  if (topic.title.empty()) throw BcfError("entry '" + entry + "': the Topic has no Title");
  topic.description = child_text(t, "Description", entry, kLong);
  topic.author = child_text(t, "CreationAuthor", entry);
  topic.assignee = child_text(t, "AssignedTo", entry);
  topic.created = time_field(t, "CreationDate", entry, true);
  topic.modified = time_field(t, "ModifiedDate", entry, false);
  topic.due = time_field(t, "DueDate", entry, false);
  for (pugi::xml_node l : t.child("Labels").children("Label")) {
    const std::string label = checked(l.text().as_string(), "Label", kShort, entry);
    if (label.find_first_not_of(" \t\r\n") != std::string::npos) topic.labels.push_back(label);
  }
  for (pugi::xml_node v : t.child("Viewpoints").children("ViewPoint")) {
    const std::string guid = guid_of(v.attribute("Guid"), "ViewPoint", entry);
    const std::string file = child_text(v, "Viewpoint", entry);
    if (file.empty() || file.find('/') != std::string::npos || !safe_name(folder + "/" + file))
      throw BcfError("entry '" + entry + "': ViewPoint " + guid + " names no file of its folder: '" + file + "'");
    if (!zip.has(folder + "/" + file)) throw BcfError("entry '" + entry + "': ViewPoint " + guid + ": " + file + " is not in the zip");
    topic.viewpoints[guid] = camera(zip.read(folder + "/" + file), folder + "/" + file);
  }
  for (pugi::xml_node c : t.child("Comments").children("Comment")) {
    BcfComment comment;
    comment.guid = guid_of(c.attribute("Guid"), "Comment", entry);
    comment.author = child_text(c, "Author", entry);
    comment.text = child_text(c, "Comment", entry, kLong);
    comment.date = time_field(c, "Date", entry, true);
    comment.viewpoint = guid_of(c.child("Viewpoint").attribute("Guid"), "Viewpoint", entry, false);
    if (!comment.viewpoint.empty() && !topic.viewpoints.count(comment.viewpoint))
      throw BcfError("entry '" + entry + "': comment " + comment.guid + " points at viewpoint " + comment.viewpoint +
                     ", which the topic does not list");
    topic.comments.push_back(std::move(comment));
  }
  return topic;
}

}  // namespace

double bcf_time(const std::string& raw) {
  // xs:dateTime may carry whitespace around it; inside, digits exactly where the form has them.
  const std::size_t first = raw.find_first_not_of(" \t\r\n"), last = raw.find_last_not_of(" \t\r\n");
  const std::string text = first == std::string::npos ? "" : raw.substr(first, last - first + 1);
  auto digits = [&](std::size_t at, std::size_t n) {
    if (at + n > text.size()) return -1;
    int v = 0;
    for (std::size_t i = at; i < at + n; ++i) {
      if (!std::isdigit(static_cast<unsigned char>(text[i]))) return -1;
      v = v * 10 + (text[i] - '0');
    }
    return v;
  };
  const int y = digits(0, 4), mo = digits(5, 2), d = digits(8, 2), h = digits(11, 2), mi = digits(14, 2), s = digits(17, 2);
  if (text.size() < 19 || y < 0 || mo < 0 || d < 0 || h < 0 || mi < 0 || s < 0 || text[4] != '-' || text[7] != '-' ||
      text[10] != 'T' || text[13] != ':' || text[16] != ':')
    throw BcfError("not a date and time (YYYY-MM-DDThh:mm:ss): '" + checked(raw.c_str(), "date", kShort, "") + "'");
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  const int days[] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (mo < 1 || mo > 12 || d < 1 || d > days[mo - 1] || h > 23 || mi > 59 || s > 59)
    throw BcfError("a date or time out of range: '" + text + "'");
  std::size_t at = 19;
  double fraction = 0;
  if (at < text.size() && text[at] == '.') {
    double scale = 0.1;
    for (++at; at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])); ++at, scale /= 10)
      fraction += (text[at] - '0') * scale;
  }
  const std::string zone = text.substr(at);
  double offset = 0;
  if (zone == "Z" || zone.empty()) {
  } else if (zone.size() == 6 && (zone[0] == '+' || zone[0] == '-') && zone[3] == ':' && digits(at + 1, 2) >= 0 &&
             digits(at + 1, 2) <= 14 && digits(at + 4, 2) >= 0 && digits(at + 4, 2) <= 59) {
    offset = (zone[0] == '+' ? 1 : -1) * (digits(at + 1, 2) * 3600.0 + digits(at + 4, 2) * 60.0);
  } else {
    throw BcfError("an unknown time zone in '" + text + "'");
  }
  std::tm t{};
  t.tm_year = y - 1900, t.tm_mon = mo - 1, t.tm_mday = d, t.tm_hour = h, t.tm_min = mi, t.tm_sec = s;
  return double(timegm(&t)) + fraction - offset;
}

std::vector<BcfTopic> read_bcf(std::string_view zip_bytes, const BcfLimits& limits) {
  Archive zip(zip_bytes, limits);
  if (!zip.has("bcf.version")) throw BcfError("no bcf.version: not a BCF file");
  {
    const pugi::xml_document doc = parse_xml(zip.read("bcf.version"), "bcf.version");
    const std::string version = checked(doc.child("Version").attribute("VersionId").as_string(), "VersionId", kShort, "bcf.version");
    if (version != "3.0") throw BcfError("bcf.version: VersionId '" + version + "', this reader knows BCF 3.0");
  }
  std::vector<BcfTopic> topics;
  for (const std::string& name : zip.names()) {
    const std::size_t slash = name.find('/');
    if (slash == std::string::npos || name.substr(slash) != "/markup.bcf") continue;
    topics.push_back(topic_of(zip, name.substr(0, slash)));
  }
  return topics;
}

}  // namespace mtcs::serve
