// mtcs serve from outside: a real server on 127.0.0.1 (any free port), driven over HTTP by
// cpp-httplib's client as a page or a script would. Every route without credentials and with
// each role, CSRF, uploads (content hash against sha256sum, the size limit on a chunked body,
// a bad mesh refused with nothing stored), the interference check against the certified pair
// count, findings across versions, review items, the live stream and its replay, and a job a
// killed server left running.

#include <httplib.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "mtcs/serve/review_server.h"
#include "mtcs/serve/review_store.h"
#include "support/paths.h"
#include "support/scratch_file.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace mtcs::serve;

namespace {

const std::string kMeshes = MTCS_TEST_DATA + "/meshes/";

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The certified pair count of homer against the gear at a placement (shared/cases).
struct Placement {
  double t[3];
  int pairs;
};
Placement certified_overlap() {
  std::ifstream in(MTCS_TEST_DATA + "/mesh_interference.csv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("homer,mcad_herringbone_gear,", 0) != 0) continue;
    std::stringstream row(line.substr(std::string("homer,mcad_herringbone_gear,").size()));
    Placement p{};
    char comma;
    row >> p.t[0] >> comma >> p.t[1] >> comma >> p.t[2] >> comma >> p.pairs;
    if (p.pairs > 0) return p;
  }
  FAIL("no overlap row of homer and the gear in mesh_interference.csv");
  return {};
}

// A server with five accounts: olga owns the server; dora, rita and vic will be a project's
// designer, reviewer and viewer; nora designs but is no member.
struct Server {
  fs::path data;
  std::unique_ptr<ReviewServer> server;
  std::thread thread;
  int port = 0;

  explicit Server(const std::string& name, bool accounts = true, double stream_seconds = 1) {
    data = mtcs_test::scratch_root() / name;
    if (accounts) {
      add_user(data, "olga", "olga-password", Role::owner);
      add_user(data, "dora", "dora-password", Role::designer);
      add_user(data, "rita", "rita-password", Role::reviewer);
      add_user(data, "vic", "vic-password", Role::viewer);
      add_user(data, "nora", "nora-password", Role::designer);
    }
    start(stream_seconds);
  }
  void start(double stream_seconds = 1) {
    ServeOptions o;
    o.data = data, o.port = 0, o.mtcs_binary = MTCS_BINARY, o.stream_seconds = stream_seconds;
    o.upload_bytes = 4u << 20, o.streams = 3;
    server = std::make_unique<ReviewServer>(o);
    port = server->bind();
    thread = std::thread([this] { server->listen(); });
  }
  void stop() {
    server->stop();
    thread.join();
    server.reset();
  }
  ~Server() {
    if (server) stop();
  }
};

// One signed-in user (cookie + CSRF header), as a page is.
struct Browser {
  httplib::Client http;
  httplib::Headers headers;

  Browser(int port, const std::string& name, const std::string& password) : http("127.0.0.1", port) {
    http.set_read_timeout(30);
    const auto r = http.Post("/api/v1/login", json{{"name", name}, {"password", password}}.dump(), "application/json");
    REQUIRE(r);
    REQUIRE(r->status == 200);
    const std::string cookie = r->get_header_value("Set-Cookie");
    headers = {{"Cookie", cookie.substr(0, cookie.find(';'))}, {"X-MTCS-CSRF", json::parse(r->body)["csrf"]}};
  }
  json get(const std::string& path, int expect = 200) {
    const auto r = http.Get(path.c_str(), headers);
    REQUIRE(r);
    INFO(path << ": " << r->body);
    REQUIRE(r->status == expect);
    return json::parse(r->body);
  }
  json send(const std::string& method, const std::string& path, const json& body, int expect) {
    httplib::Result r = method == "POST"  ? http.Post(path.c_str(), headers, body.dump(), "application/json")
                        : method == "PUT" ? http.Put(path.c_str(), headers, body.dump(), "application/json")
                                          : http.Patch(path.c_str(), headers, body.dump(), "application/json");
    REQUIRE(r);
    INFO(method << " " << path << ": " << r->body);
    REQUIRE(r->status == expect);
    return json::parse(r->body);
  }
  json upload(long project, const std::string& component, const fs::path& file, int expect) {
    const std::string path = "/api/v1/projects/" + std::to_string(project) + "/components/" + component +
                             "/versions?file=" + file.filename().string();
    const auto r = http.Post(path.c_str(), headers, read_file(file), "application/octet-stream");
    REQUIRE(r);
    INFO(path << ": " << r->body);
    REQUIRE(r->status == expect);
    return json::parse(r->body);
  }
};

// The status of a request written byte for byte on a new connection (its head only, no body).
int raw_status(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(std::uint16_t(port));
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&to), sizeof to) != 0) return -1;
  if (::write(fd, request.data(), request.size()) != ssize_t(request.size())) return -1;
  char reply[64] = {};
  const ssize_t n = ::read(fd, reply, sizeof reply - 1);
  ::close(fd);
  int status = -1;
  if (n > 12) std::sscanf(reply, "HTTP/1.%*d %d", &status);
  return status;
}

json wait_for_job(Browser& b, long project, long job) {
  const std::string path = "/api/v1/projects/" + std::to_string(project) + "/jobs/" + std::to_string(job);
  for (int i = 0; i < 600; ++i) {
    json j = b.get(path);
    if (j["state"] != "queued" && j["state"] != "running") return j;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  FAIL("the job did not end in 30 s");
  return {};
}

// A project of olga's with dora, rita and vic as designer, reviewer and viewer.
long team_project(Browser& olga) {
  const long p = olga.send("POST", "/api/v1/projects", {{"name", "slide"}}, 201)["id"];
  for (auto [user, role] : {std::pair{"dora", "designer"}, {"rita", "reviewer"}, {"vic", "viewer"}})
    olga.send("PUT", "/api/v1/projects/" + std::to_string(p) + "/members", {{"user", user}, {"role", role}}, 200);
  return p;
}

int status_of(httplib::Client& http, const std::string& method, const std::string& path, const httplib::Headers& h) {
  httplib::Result r = method == "GET"    ? http.Get(path.c_str(), h)
                      : method == "POST" ? http.Post(path.c_str(), h, "", "text/plain")
                      : method == "PUT"  ? http.Put(path.c_str(), h, "", "text/plain")
                                         : http.Patch(path.c_str(), h, "", "text/plain");
  return r ? r->status : -1;
}

}  // namespace

TEST_CASE("mtcs serve: every route but sign-in refuses a caller without credentials", "[serve]") {
  Server s("open");
  httplib::Client http("127.0.0.1", s.port);
  int checked = 0;
  for (const RouteInfo& route : route_table()) {
    if (route.access == Access::open) continue;
    INFO(route.method << " " << route.example);
    CHECK(status_of(http, route.method, route.example, {}) == 401);
    CHECK(status_of(http, route.method, route.example, {{"Authorization", "Bearer " + std::string(64, 'a')}}) == 401);
    CHECK(status_of(http, route.method, route.example, {{"Cookie", "mtcs_session=forged"}}) == 401);
    ++checked;
  }
  CHECK(checked == int(route_table().size()) - 5);  // sign-in and the app's four files are open
  // The app's page: a strict CSP (no inline script), its script from the server itself.
  const auto page = http.Get("/");
  REQUIRE(page);
  CHECK(page->status == 200);
  CHECK(page->get_header_value("Content-Security-Policy").find("unsafe-inline") == std::string::npos);
  CHECK(page->body.find("<script type=\"module\" src=\"/app.js\">") != std::string::npos);
  CHECK(http.Get("/app.js")->body.find("innerHTML") == std::string::npos);
  // Outside the table: 404, whatever the path tries.
  for (const char* path : {"/etc/passwd", "/api/v1/../../etc/passwd", "/api/%2e%2e/%2e%2e/etc/passwd",
                           "/api/v1/projects/1/versions/..%2f..%2fserve.sqlite/file"})
    CHECK(status_of(http, "GET", path, {}) == 404);
}

TEST_CASE("mtcs serve: the route x role matrix, members and strangers", "[serve]") {
  Server s("roles");
  Browser olga(s.port, "olga", "olga-password");
  const long p = team_project(olga);
  REQUIRE(p == 1);  // the table's examples name project 1
  const std::map<std::string, Role> members{{"olga", Role::owner}, {"dora", Role::designer}, {"rita", Role::reviewer},
                                            {"vic", Role::viewer}};
  for (const auto& [name, role] : members) {
    Browser b(s.port, name, name + "-password");
    for (const RouteInfo& route : route_table()) {
      if (route.access != Access::member) continue;
      const int status = status_of(b.http, route.method, route.example, b.headers);
      INFO(name << " (" << to_string(role) << ") " << route.method << " " << route.example << " -> " << status);
      if (at_least(role, route.least)) CHECK((status != 401 && status != 403));
      else CHECK(status == 403);
    }
    // Creating projects: designers and owners of the server.
    const int create = status_of(b.http, "POST", "/api/v1/projects", b.headers);
    CHECK((create == 403) == !at_least(role, Role::designer));
  }
  // A designer of the server who is no member does not learn the project exists.
  Browser nora(s.port, "nora", "nora-password");
  for (const RouteInfo& route : route_table())
    if (route.access == Access::member) {
      INFO("nora " << route.method << " " << route.example);
      CHECK(status_of(nora.http, route.method, route.example, nora.headers) == 404);
    }
  CHECK(nora.get("/api/v1/projects").empty());
}

TEST_CASE("mtcs serve: sign-in, CSRF, API tokens and the login limit", "[serve]") {
  Server s("auth");
  httplib::Client http("127.0.0.1", s.port);
  // Wrong password and unknown user answer alike.
  for (const char* name : {"olga", "nobody"}) {
    const auto r = http.Post("/api/v1/login", json{{"name", name}, {"password", "wrong-password"}}.dump(), "application/json");
    REQUIRE(r);
    CHECK(r->status == 401);
    CHECK(json::parse(r->body)["error"] == "wrong name or password");
  }
  CHECK(http.Post("/api/v1/login", "{not json", "application/json")->status == 400);
  CHECK(http.Post("/api/v1/login", "name=olga", "application/x-www-form-urlencoded")->status == 415);

  Browser olga(s.port, "olga", "olga-password");
  const std::string cookie = olga.headers.find("Cookie")->second;
  // A session's write without the CSRF header, with a wrong one, or from another site: 403.
  CHECK(http.Post("/api/v1/projects", {{"Cookie", cookie}}, R"({"name":"a"})", "application/json")->status == 403);
  CHECK(http.Post("/api/v1/projects", {{"Cookie", cookie}, {"X-MTCS-CSRF", std::string(64, '0')}}, R"({"name":"a"})",
                  "application/json")->status == 403);
  auto cross = olga.headers;
  cross.emplace("Sec-Fetch-Site", "cross-site");
  CHECK(http.Post("/api/v1/projects", cross, R"({"name":"a"})", "application/json")->status == 403);
  CHECK(olga.send("POST", "/api/v1/projects", {{"name", "a"}}, 201)["id"] == 1);
  olga.send("POST", "/api/v1/projects", {{"name", "a"}}, 409);

  // An API token: no cookie, no CSRF header; stored only as a digest.
  const std::string token = olga.send("POST", "/api/v1/tokens", {{"name", "ci"}}, 201)["token"];
  const httplib::Headers bearer{{"Authorization", "Bearer " + token}};
  const auto r = http.Post("/api/v1/projects", bearer, R"({"name":"b"})", "application/json");
  REQUIRE(r);
  CHECK(r->status == 201);
  CHECK(http.Post("/api/v1/tokens", bearer, R"({"name":"again"})", "application/json")->status == 403);
  CHECK(read_file(s.data / "serve.sqlite").find(token) == std::string::npos);

  // Sign-out ends the session.
  CHECK(http.Post("/api/v1/logout", olga.headers, "{}", "application/json")->status == 200);
  CHECK(http.Get("/api/v1/me", {{"Cookie", cookie}})->status == 401);

  // Five failures a minute per account, then 429 even with the right password.
  for (int i = 0; i < 5; ++i)
    http.Post("/api/v1/login", json{{"name", "vic"}, {"password", "wrong-password"}}.dump(), "application/json");
  const auto limited = http.Post("/api/v1/login", json{{"name", "vic"}, {"password", "vic-password"}}.dump(), "application/json");
  REQUIRE(limited);
  CHECK(limited->status == 429);
}

TEST_CASE("mtcs serve: uploads by content, the size limit, a bad mesh refused with nothing stored", "[serve]") {
  Server s("uploads");
  Browser olga(s.port, "olga", "olga-password");
  const long p = team_project(olga);
  Browser dora(s.port, "dora", "dora-password");
  const json v1 = dora.upload(p, "homer", kMeshes + "homer.off", 201);
  CHECK(v1["seq"] == 1);
  CHECK(v1["stats"]["triangles"].get<int>() > 0);
  // The hash is the file's SHA-256 as sha256sum computes it, and the stored bytes are the file's.
  FILE* pipe = ::popen(("sha256sum " + kMeshes + "homer.off").c_str(), "r");
  REQUIRE(pipe);
  char digest[65] = {};
  REQUIRE(std::fread(digest, 1, 64, pipe) == 64);
  ::pclose(pipe);
  CHECK(v1["blob"] == std::string(digest));
  const std::string blob = v1["blob"];
  CHECK(read_file(s.data / "blobs/sha256" / blob.substr(0, 2) / blob.substr(2, 2) / blob) == read_file(kMeshes + "homer.off"));
  // The same bytes again: the same version, one file.
  const json again = dora.upload(p, "homer", kMeshes + "homer.off", 200);
  CHECK(again["id"] == v1["id"]);
  CHECK(again["new"] == false);
  // The same bytes as another component: a version of its own, still one file.
  dora.upload(p, "homer-copy", kMeshes + "homer.off", 201);
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(s.data / "blobs")) files += e.is_regular_file();
  CHECK(files == 1);

  // Not a solid: refused with the reader's reason under the user's file name; nothing stored.
  const fs::path open_box = mtcs_test::scratch_root() / "open_box.off";
  std::ofstream(open_box) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";
  const json refused = dora.upload(p, "box", open_box, 400);
  CHECK(refused["error"].get<std::string>().find("open_box.off") != std::string::npos);
  CHECK(refused["error"].get<std::string>().find("tmp") == std::string::npos);
  CHECK(dora.get("/api/v1/projects/1/components").size() == 2);
  // Not a mesh format, a folder in the name: refused before a byte is read.
  CHECK(dora.http.Post("/api/v1/projects/1/components/box/versions?file=box.exe", dora.headers, "MZ", "application/octet-stream")->status == 415);
  CHECK(dora.http.Post("/api/v1/projects/1/components/box/versions?file=../box.stl", dora.headers, "x", "application/octet-stream")->status == 400);

  // Past the limit (4 MiB here), sent chunked with no length: 413, no file left behind.
  std::size_t sent = 0;
  const auto big = dora.http.Post(
      "/api/v1/projects/1/components/big/versions?file=big.stl", dora.headers,
      [&](std::size_t, httplib::DataSink& sink) {
        const std::string chunk(1 << 16, 'x');
        sink.write(chunk.data(), chunk.size());
        if ((sent += chunk.size()) >= (16u << 20)) sink.done();
        return true;
      },
      "application/octet-stream");
  if (big) CHECK(big->status == 413);  // the server may close before the client reads the answer
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  CHECK(fs::is_empty(s.data / "tmp"));
  files = 0;
  for (const auto& e : fs::recursive_directory_iterator(s.data / "blobs")) files += e.is_regular_file();
  CHECK(files == 1);
  // A JSON route takes no chunked body and none over its limit (1 MiB), signed in or not (a new
  // connection: the server closed the last one after its 413).
  // Announced by the request's head alone (the server answers before reading any body).
  const std::string head = "POST /api/v1/projects/1/topics HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n" +
                           std::string("Cookie: ") + dora.headers.find("Cookie")->second + "\r\nX-MTCS-CSRF: " +
                           dora.headers.find("X-MTCS-CSRF")->second + "\r\n";
  CHECK(raw_status(s.port, head + "Transfer-Encoding: chunked\r\n\r\n") == 411);
  CHECK(raw_status(s.port, head + "Content-Length: 2097152\r\n\r\n") == 413);
  CHECK(raw_status(s.port, head + "Transfer-Encoding: Chunked\r\n\r\n") == 411);
  // Before sign-in too: a body with no length, a chunked one, an oversized upload (4 MiB here).
  const std::string login = "POST /api/v1/login HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n";
  CHECK(raw_status(s.port, login + "\r\n") == 411);
  CHECK(raw_status(s.port, login + "Transfer-Encoding: chunked\r\n\r\n") == 411);
  CHECK(raw_status(s.port, "POST /api/v1/projects/1/components/big/versions?file=big.stl HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                           "Content-Length: 5000000\r\n\r\n") == 413);
  const auto topics = httplib::Client("127.0.0.1", s.port).Get("/api/v1/projects/1/topics", dora.headers);
  REQUIRE(topics);
  CHECK(json::parse(topics->body).empty());
  // A viewer reads the stored file back, byte for byte.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  Browser vic(s.port, "vic", "vic-password");
  const auto back = vic.http.Get(("/api/v1/projects/1/versions/" + std::to_string(v1["id"].get<long>()) + "/file").c_str(), vic.headers);
  REQUIRE(back);
  CHECK(back->body == read_file(kMeshes + "homer.off"));
}

TEST_CASE("mtcs serve: the interference check on the server, findings across versions, an item that follows one", "[serve]") {
  Server s("check", true, 30);
  Browser olga(s.port, "olga", "olga-password");
  const long p = team_project(olga);
  Browser dora(s.port, "dora", "dora-password");
  Browser rita(s.port, "rita", "rita-password");
  dora.upload(p, "homer", kMeshes + "homer.off", 201);
  dora.upload(p, "gear", kMeshes + "mcad_herringbone_gear.off", 201);
  const Placement at = certified_overlap();
  const json check{{"kind", "interference"}, {"a", "homer"}, {"b", "gear"}, {"translate", {at.t[0], at.t[1], at.t[2]}}};
  // A reviewer may not start checks.
  rita.send("POST", "/api/v1/projects/1/jobs", check, 403);

  const long first = dora.send("POST", "/api/v1/projects/1/jobs", check, 202)["id"];
  json job = wait_for_job(dora, p, first);
  INFO(job.dump());
  REQUIRE(job["state"] == "succeeded");
  CHECK(job["result"]["pair_count"] == at.pairs);  // the certified count
  CHECK(job["result"]["interferes"] == true);
  int grouped = 0;
  for (const json& f : job["findings"]) {
    CHECK(f["state"] == "new");
    grouped += f["payload"]["pairs"].get<int>();
  }
  CHECK(grouped == at.pairs);
  const std::string key = job["findings"][0]["key"];
  // The check's own 3-D page, with a CSP of its own.
  const auto page = rita.http.Get("/api/v1/projects/1/jobs/1/page", rita.headers);
  REQUIRE(page);
  CHECK(page->status == 200);
  CHECK(page->body.find("mtcsInterference") != std::string::npos);
  CHECK(page->get_header_value("Content-Security-Policy").find("frame-ancestors 'self'") != std::string::npos);

  // An item on the first finding, with a viewpoint; the reviewer may, the viewer may not.
  const json viewpoint{{"camera_view_point", {10, 20, 30}}, {"camera_direction", {0, 0, -1}},
                       {"camera_up_vector", {0, 1, 0}},      {"field_of_view", 45},
                       {"aspect_ratio", 1.6},                {"target", {10, 20, 0}},
                       {"job", 1}};
  const json item = rita.send("POST", "/api/v1/projects/1/topics",
                              {{"title", "homer's foot in the gear"}, {"finding", key}, {"comment", "see here"},
                               {"viewpoint", viewpoint}},
                              201);
  CHECK(item["comments"][0]["viewpoint"] == viewpoint);  // restored as saved
  CHECK(item["authorization"]["topic_actions"].size() > 0);
  Browser vic(s.port, "vic", "vic-password");
  vic.send("POST", "/api/v1/projects/1/topics", {{"title", "x"}}, 403);
  CHECK(vic.get("/api/v1/projects/1/topics/1")["authorization"]["topic_actions"].empty());

  // The items as BCF-XML 3.0: valid against buildingSMART's schemas, the camera in metres, the
  // same GUIDs on a second export.
  const auto bcf = vic.http.Get("/api/v1/projects/1/bcf", vic.headers);
  REQUIRE(bcf);
  REQUIRE(bcf->status == 200);
  const fs::path bcf_file = mtcs_test::scratch_root() / "project.bcf";
  std::ofstream(bcf_file, std::ios::binary) << bcf->body;
  CHECK(std::system(("python3 " + MTCS_SOURCE_DIR + "/tests/serve/check_bcf.py " + bcf_file.string() + " " + MTCS_TEST_DATA +
                     "/bcf/schemas 1 10,20,30").c_str()) == 0);
  const auto again = vic.http.Get("/api/v1/projects/1/bcf", vic.headers);
  REQUIRE(again);
  auto guids = [](const std::string& zip) {  // the file names in the zip's central directory
    std::vector<std::string> names;
    for (auto at = zip.find("markup.bcf"); at != std::string::npos; at = zip.find("markup.bcf", at + 1))
      names.push_back(zip.substr(at - 37, 36));
    return names;
  };
  CHECK(guids(again->body) == guids(bcf->body));
  CHECK_FALSE(guids(bcf->body).empty());
  // BCF import: the project's own export adds nothing; buildingSMART's Labels case adds its item
  // with its comment, told live; a viewer may not import; a file that is no BCF is a 400.
  auto topics = [&] { return json::parse(dora.http.Get("/api/v1/projects/1/topics", dora.headers)->body); };
  const std::size_t items = topics().size();
  auto import = [&](Browser& who, const std::string& bytes) {
    return who.http.Post("/api/v1/projects/1/bcf", who.headers, bytes, "application/octet-stream");
  };
  auto own = import(dora, bcf->body);
  REQUIRE(own);
  INFO(own->body);
  CHECK(own->status == 200);
  CHECK(json::parse(own->body)["topics_added"] == 0);
  CHECK(json::parse(own->body)["comments_added"] == 0);
  auto labels = import(dora, read_file(fs::path(MTCS_TEST_DATA) / "bcf/test_cases/Labels.bcf"));
  REQUIRE(labels);
  CHECK(labels->status == 200);
  CHECK(json::parse(labels->body)["topics_added"] == 1);
  const json after = topics();
  CHECK(after.size() == items + 1);
  CHECK(after.back()["title"] == "Labels");
  CHECK(after.back()["labels"] == json::array({"Architects"}));
  CHECK(import(vic, bcf->body)->status == 403);
  auto junk = import(dora, "not a zip at all");
  CHECK(junk->status == 400);
  CHECK_THAT(junk->body, Catch::Contains("the BCF file"));
  CHECK(topics().size() == items + 1);
  // Exported again: the imported item under its own GUID with its labels, valid against the schemas.
  const auto both = vic.http.Get("/api/v1/projects/1/bcf", vic.headers);
  REQUIRE(both);
  std::ofstream(bcf_file, std::ios::binary | std::ios::trunc) << both->body;
  CHECK(std::system(("python3 " + MTCS_SOURCE_DIR + "/tests/serve/check_bcf.py " + bcf_file.string() + " " + MTCS_TEST_DATA +
                     "/bcf/schemas " + std::to_string(items + 1) + " 10,20,30").c_str()) == 0);
  CHECK(both->body.find("bee19eb8-3ec0-4e0d-90df-52afc806beaf/markup.bcf") != std::string::npos);

  // The same check again: every finding persistent, the item told so.
  const long second = dora.send("POST", "/api/v1/projects/1/jobs", check, 202)["id"];
  job = wait_for_job(dora, p, second);
  REQUIRE(job["state"] == "succeeded");
  for (const json& f : job["findings"]) CHECK(f["state"] == "persistent");

  // A corrected gear (moved 100 mm along x): a new version; the check finds nothing, and every
  // finding of the last check is resolved, the item's too, with mtcs's note on it.
  std::ifstream in(kMeshes + "mcad_herringbone_gear.off");
  std::string header;
  int nv, nf, ne;
  in >> header >> nv >> nf >> ne;
  std::ostringstream moved;
  moved.precision(17);
  moved << "OFF\n" << nv << " " << nf << " " << ne << "\n";
  for (int i = 0; i < nv; ++i) {
    double x, y, z;
    in >> x >> y >> z;
    moved << x + 100 << " " << y << " " << z << "\n";
  }
  moved << in.rdbuf();
  const fs::path gear2 = mtcs_test::scratch_root() / "gear_moved.off";
  std::ofstream(gear2) << moved.str();
  CHECK(dora.upload(p, "gear", gear2, 201)["seq"] == 2);
  const long third = dora.send("POST", "/api/v1/projects/1/jobs", check, 202)["id"];
  job = wait_for_job(dora, p, third);
  REQUIRE(job["state"] == "succeeded");
  CHECK(job["result"]["pair_count"] == 0);
  CHECK(job["result"]["findings"]["resolved"].get<int>() == int(job["findings"].size()));
  bool item_resolved = false;
  for (const json& f : job["findings"]) item_resolved |= f["key"] == key && f["state"] == "resolved";
  CHECK(item_resolved);
  const json comments = rita.get("/api/v1/projects/1/topics/1")["comments"];
  REQUIRE(comments.size() == 3);  // rita's, "still there", "no longer found"
  CHECK(comments[2]["author"] == "mtcs");
  CHECK(comments[2]["text"].get<std::string>().find("resolved") != std::string::npos);

  // Cancel: a queued check (one runs at a time here) never runs; an ended one cannot be.
  const long running = dora.send("POST", "/api/v1/projects/1/jobs", check, 202)["id"];
  const long waiting = dora.send("POST", "/api/v1/projects/1/jobs", check, 202)["id"];
  dora.send("POST", "/api/v1/projects/1/jobs/" + std::to_string(waiting) + "/cancel", json::object(), 202);
  CHECK(wait_for_job(dora, p, waiting)["state"] == "cancelled");
  CHECK(wait_for_job(dora, p, running)["state"] == "succeeded");
  dora.send("POST", "/api/v1/projects/1/jobs/" + std::to_string(running) + "/cancel", json::object(), 409);
  rita.send("POST", "/api/v1/projects/1/jobs/" + std::to_string(running) + "/cancel", json::object(), 403);

  // A bad input of a check fails with the CLI's message.
  const json wrong = dora.send("POST", "/api/v1/projects/1/jobs", {{"kind", "interference"}, {"a", "homer"}, {"b", "nothing"}}, 404);
  CHECK(wrong["error"].get<std::string>().find("'b'") != std::string::npos);
  dora.send("POST", "/api/v1/projects/1/jobs", {{"kind", "interference"}, {"a", "homer"}, {"b", "gear"}, {"translate", {1, 2}}}, 400);
}

TEST_CASE("mtcs serve: live events in order, replayed from Last-Event-ID, capped streams", "[serve]") {
  Server s("live", true, 2);
  Browser olga(s.port, "olga", "olga-password");
  REQUIRE(team_project(olga) == 1);
  Browser rita(s.port, "rita", "rita-password");
  for (int i = 0; i < 3; ++i) rita.send("POST", "/api/v1/projects/1/topics", {{"title", "item " + std::to_string(i)}}, 201);
  // A stream from the start: the members' changes and the three items, ids increasing.
  std::string text;
  Browser vic(s.port, "vic", "vic-password");
  auto r = vic.http.Get("/api/v1/projects/1/events", vic.headers, [&](const char* d, std::size_t n) {
    text.append(d, n);
    return true;
  });
  REQUIRE(r);
  CHECK(r->status == 200);
  CHECK(r->get_header_value("Content-Type") == "text/event-stream");
  std::vector<long> ids;
  std::vector<std::string> types;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("id: ", 0) == 0) ids.push_back(std::stol(line.substr(4)));
    if (line.rfind("event: ", 0) == 0) types.push_back(line.substr(7));
  }
  REQUIRE(types.size() == 6);  // three members, three items
  CHECK(std::count(types.begin(), types.end(), "topic.created") == 3);
  CHECK(std::is_sorted(ids.begin(), ids.end()));
  // Reconnecting with the last id seen: only what came after.
  rita.send("POST", "/api/v1/projects/1/topics/2/comments", {{"text", "on it"}}, 201);
  text.clear();
  auto h = vic.headers;
  h.emplace("Last-Event-ID", std::to_string(ids.back()));
  r = vic.http.Get("/api/v1/projects/1/events", h, [&](const char* d, std::size_t n) {
    text.append(d, n);
    return true;
  });
  REQUIRE(r);
  CHECK(text.find("event: comment.created") != std::string::npos);
  CHECK(text.find("event: topic.created") == std::string::npos);
  CHECK(text.find("on it") != std::string::npos);
  // A live event reaches an open stream while it waits.
  text.clear();
  std::thread later([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    rita.send("PATCH", "/api/v1/projects/1/topics/1", {{"status", "in_progress"}}, 200);
  });
  h = vic.headers;
  h.emplace("Last-Event-ID", std::to_string(ids.back() + 1));
  r = vic.http.Get("/api/v1/projects/1/events", h, [&](const char* d, std::size_t n) {
    text.append(d, n);
    return true;
  });
  later.join();
  CHECK(text.find("event: topic.updated") != std::string::npos);
  rita.send("PATCH", "/api/v1/projects/1/topics/1", {{"status", "done"}}, 400);

  // The cap (3 here): a fourth stream is told to come back (503, Retry-After) while the three
  // last, and the rest of the API still answers.
  std::vector<std::thread> open;
  std::atomic<int> served{0};
  for (int i = 0; i < 3; ++i)
    open.emplace_back([&] {
      httplib::Client c("127.0.0.1", s.port);
      c.set_read_timeout(30);
      if (const auto r = c.Get("/api/v1/projects/1/events", vic.headers, [](const char*, std::size_t) { return true; });
          r && r->status == 200)
        ++served;
    });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  httplib::Client fourth("127.0.0.1", s.port);
  const auto refused = fourth.Get("/api/v1/projects/1/events", vic.headers);
  REQUIRE(refused);
  CHECK(refused->status == 503);
  CHECK(refused->get_header_value("Retry-After") == "5");
  CHECK(fourth.Get("/api/v1/me", vic.headers)->status == 200);
  for (auto& t : open) t.join();
  CHECK(served == 3);
}

TEST_CASE("mtcs serve: a job a killed server left running is interrupted, never lost", "[serve]") {
  Server s("restart");
  Browser olga(s.port, "olga", "olga-password");
  const long p = team_project(olga);
  s.stop();
  {
    ReviewStore store(s.data / "serve.sqlite");
    const long job = store.add_job(p, "interference", {{"a", 1}, {"b", 2}, {"translate", {0, 0, 0}}}, "scope", 1);
    REQUIRE(store.claim_next()->id == job);  // running, as a killed server leaves it
  }
  s.start();
  Browser again(s.port, "olga", "olga-password");
  const json jobs = again.get("/api/v1/projects/1/jobs");
  REQUIRE(jobs.size() == 1);
  CHECK(jobs[0]["state"] == "interrupted");
}

namespace {

// `mtcs serve` as its own process, as a user starts it: the port it prints, and kill -9.
struct ServeProcess {
  pid_t pid = -1;
  int port = 0;
  explicit ServeProcess(const fs::path& data) {
    const fs::path log = data.string() + ".log";
    fs::create_directories(data.parent_path());
    pid = ::fork();
    if (pid == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlives the test
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::execl(MTCS_BINARY.c_str(), MTCS_BINARY.c_str(), "serve", "--data", data.c_str(), "--port", "0", nullptr);
      ::_exit(127);
    }
    for (int i = 0; i < 200 && port == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      const std::string text = read_file(log);
      if (const auto at = text.find("127.0.0.1:"); at != std::string::npos) port = std::stoi(text.substr(at + 10));
    }
    if (port == 0) kill9();
    REQUIRE(port > 0);
  }
  void kill9() {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    pid = -1;
  }
  ~ServeProcess() {
    if (pid > 0) kill9();
  }
};

}  // namespace

TEST_CASE("mtcs serve: kill -9 during a check and after an upload loses nothing acknowledged", "[serve]") {
  const fs::path data = mtcs_test::scratch_root() / "killed";
  add_user(data, "olga", "olga-password", Role::owner);
  long job = 0;
  std::string blob;
  {
    ServeProcess server(data);
    Browser olga(server.port, "olga", "olga-password");
    olga.send("POST", "/api/v1/projects", {{"name", "p"}}, 201);
    // The two largest certified meshes: a check long enough to be killed in.
    blob = olga.upload(1, "fandisk", kMeshes + "fandisk_large.off", 201)["blob"];
    olga.upload(1, "turbine", kMeshes + "turbine.off", 201);
    job = olga.send("POST", "/api/v1/projects/1/jobs", {{"kind", "interference"}, {"a", "fandisk"}, {"b", "turbine"}}, 202)["id"];
    for (int i = 0; i < 200 && olga.get("/api/v1/projects/1/jobs/" + std::to_string(job))["state"] == "queued"; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    server.kill9();
  }
  // An upload cut by kill -9 half-way: nothing of it is stored, its staged part goes at restart.
  {
    ServeProcess server(data);
    Browser olga(server.port, "olga", "olga-password");
    std::thread killer([&] {
      for (int i = 0; i < 400 && fs::is_empty(data / "tmp"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      server.kill9();
    });
    olga.http.Post(
        "/api/v1/projects/1/components/half/versions?file=half.off", olga.headers,
        [](std::size_t offset, httplib::DataSink& sink) {
          const std::string chunk(1 << 12, ' ');
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
          return offset < (3u << 20) && sink.write(chunk.data(), chunk.size());
        },
        "application/octet-stream");
    killer.join();
    CHECK(!fs::is_empty(data / "tmp"));  // the part it had received
  }
  // The check's own process died with the server (no mtcs interfere is left running).
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const fs::path folder = fs::weakly_canonical(data / "jobs" / std::to_string(job));
  int left = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    std::error_code none;
    left += fs::read_symlink(e.path() / "cwd", none) == folder;
  }
  CHECK(left == 0);
  ServeProcess again(data);
  Browser olga(again.port, "olga", "olga-password");
  const json j = olga.get("/api/v1/projects/1/jobs/" + std::to_string(job));
  CHECK((j["state"] == "interrupted" || j["state"] == "succeeded"));  // never lost, never left running
  const json components = olga.get("/api/v1/projects/1/components");
  REQUIRE(components.size() == 2);  // not the cut one
  CHECK(fs::is_empty(data / "tmp"));
  CHECK(components[0]["versions"][0]["blob"] == blob);
  CHECK(read_file(data / "blobs/sha256" / blob.substr(0, 2) / blob.substr(2, 2) / blob) == read_file(kMeshes + "fandisk_large.off"));
}

TEST_CASE("mtcs serve: the command's errors exit 2 before anything is served, and SIGTERM stops it", "[serve]") {
  const fs::path data = mtcs_test::scratch_root() / "command";
  fs::create_directories(mtcs_test::scratch_root());
  auto run = [&](const std::string& args, const std::string& password = "") {
    const std::string input = password.empty() ? "true" : "printf '%s\\n' '" + password + "'";
    const int status = std::system(("cd " + mtcs_test::scratch_root().string() + " && " + input + " | " + MTCS_BINARY +
                                    " serve " + args + " > command.out 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  const std::string out = (mtcs_test::scratch_root() / "command.out").string();
  CHECK(run("--data " + data.string() + " --add-user anna --role owner") == 2);  // no password
  CHECK(read_file(out).find("at least 8 characters") != std::string::npos);
  CHECK(run("--data " + data.string() + " --add-user anna --role owner", "a long passphrase") == 0);
  CHECK(run("--data " + data.string() + " --add-user anna --role viewer", "another passphrase") == 2);
  CHECK(read_file(out).find("exists already") != std::string::npos);
  CHECK(run("--data " + data.string() + " --add-user bob --role boss", "a long passphrase") == 2);
  CHECK(run("--data " + data.string() + " --bind 0.0.0.0") == 2);
  CHECK(read_file(out).find("not loopback") != std::string::npos);
  // A data folder served already, a port in use: exit 2 saying so.
  ServeProcess first(data);
  CHECK(run("--data " + data.string() + " --port 0") == 2);
  CHECK(read_file(out).find("served by another mtcs serve") != std::string::npos);
  CHECK(run("--data " + data.string() + "-2 --port " + std::to_string(first.port)) == 2);
  CHECK(read_file(out).find("another server answers there") != std::string::npos);
  // SIGTERM: the server stops, exit 0.
  ::kill(first.pid, SIGTERM);
  int status = 0;
  ::waitpid(first.pid, &status, 0);
  first.pid = -1;
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("mtcs serve: docs/serve.md lists every route with its least role", "[serve]") {
  const std::string doc = read_file(MTCS_SOURCE_DIR + "/docs/serve.md");
  for (const RouteInfo& route : route_table()) {
    // The pattern as the table writes it: P, V, J, T for the ids after their folder, NAME.
    std::string path = route.pattern;
    for (const auto& [folder, letter] : {std::pair{"projects/", "P"}, {"versions/", "V"}, {"jobs/", "J"}, {"topics/", "T"}}) {
      const std::string id = std::string(folder) + R"((\d+))";
      if (const auto at = path.find(id); at != std::string::npos) path.replace(at, id.size(), std::string(folder) + letter);
    }
    const std::string name = "([A-Za-z0-9_.-]{1,64})";
    if (const auto at = path.find(name); at != std::string::npos) path.replace(at, name.size(), "NAME");
    const std::string least = route.access == Access::open        ? "anyone"
                              : route.access == Access::signed_in ? "signed in"
                              : route.access == Access::creator   ? "server role designer"
                                                                  : to_string(route.least);
    // A row of the table with the method, the route (ending there) and the least role.
    bool listed = false;
    std::istringstream lines(doc);
    for (std::string row; std::getline(lines, row);) {
      if (row.rfind("| " + route.method + " |", 0) != 0 || row.find("| " + least) == std::string::npos) continue;
      for (auto at = row.find("`" + path); at != std::string::npos; at = row.find("`" + path, at + 1)) {
        const char next = row[at + 1 + path.size()];
        listed |= next == '`' || next == '?' || next == ' ';
      }
    }
    INFO(route.method << " " << path << " (" << least << ")");
    CHECK(listed);
  }
}
