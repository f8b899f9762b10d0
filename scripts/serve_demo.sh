#!/usr/bin/env bash
# The review server on the bundled molds, in one command: installs what `mtcs serve` needs,
# builds mtcs, makes runs/demo-review with an owner account (its password printed), a project
# holding the bundled part meshes (molds/meshes) and one interference check run on the server
# (the gear's teeth through the cup's wall), then serves http://127.0.0.1:PORT until Ctrl-C.
#   serve_demo.sh [--port N] [--check]
#   --port N  where to listen (default 8421; 0: any free port)
#   --check   stop once the check has finished (what the test of this script runs)
# MTCS=path/to/mtcs skips the install and the build; MTCS_REVIEW_DATA=DIR puts the data elsewhere.
set -euo pipefail
cd "$(dirname "$0")/.."
port=8421 check=0
while [ $# -gt 0 ]; do
  case "$1" in
    --port) port=$2; shift 2 ;;
    --check) check=1; shift ;;
    *) echo "usage: serve_demo.sh [--port N] [--check]" >&2; exit 2 ;;
  esac
done
if [ -z "${MTCS:-}" ]; then
  bash scripts/setup.sh --serve
  MTCS_BUILD_TARGET=mtcs bash scripts/build.sh -DMTCS_WITH_SERVE=ON
  MTCS=./build/mtcs
fi
data=${MTCS_REVIEW_DATA:-runs/demo-review}
rm -rf "$data" "$data.log"
mkdir -p "$(dirname "$data")"
password=$(python3 -c 'import secrets; print(secrets.token_urlsafe(12))')
echo "$password" | "$MTCS" serve --data "$data" --add-user demo --role owner >/dev/null
"$MTCS" serve --data "$data" --port "$port" > "$data.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true; wait $server 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  grep -q "listening on" "$data.log" && break
  kill -0 $server 2>/dev/null || { cat "$data.log" >&2; exit 1; }
  sleep 0.1
done
url=$(sed -n 's/^mtcs serve: listening on \(http:[^ ]*\).*/\1/p' "$data.log")
python3 - "$url" "$password" <<'PY'
# The project, its components and the check, through the API as any script would.
import json, sys, time, urllib.request
url, password = sys.argv[1:]
cookie, csrf = "", ""
def call(method, path, body=None, raw=None):
    global cookie
    data = raw if raw is not None else (json.dumps(body).encode() if body is not None else None)
    req = urllib.request.Request(url + path, data=data, method=method, headers={
        "Content-Type": "application/octet-stream" if raw is not None else "application/json",
        "Cookie": cookie, "X-MTCS-CSRF": csrf})
    with urllib.request.urlopen(req) as r:
        if r.headers.get("Set-Cookie"): cookie = r.headers["Set-Cookie"].split(";")[0]
        return json.load(r)
csrf = call("POST", "/api/v1/login", {"name": "demo", "password": password})["csrf"]
project = call("POST", "/api/v1/projects", {"name": "bundled molds"})["id"]
for name, file in [("cup", "cup.off"), ("gear", "mcad_herringbone_gear.off"), ("l-bracket", "l_bracket.off"),
                   ("ribbed-box", "ribbed_box.off")]:
    with open("molds/meshes/" + file, "rb") as f:
        v = call("POST", f"/api/v1/projects/{project}/components/{name}/versions?file={file}", raw=f.read())
    print(f"uploaded {name}: {v['stats']['triangles']} triangles, sha256 {v['blob'][:12]}...")
job = call("POST", f"/api/v1/projects/{project}/jobs",
           {"kind": "interference", "a": "gear", "b": "cup", "translate": [-15, -90, -45]})["id"]
for _ in range(600):
    j = call("GET", f"/api/v1/projects/{project}/jobs/{job}")
    if j["state"] not in ("queued", "running"): break
    time.sleep(0.1)
if j["state"] != "succeeded": sys.exit(f"the check {j['state']}: {j['message']}")
r = j["result"]
print(f"check #{job}, the gear against the cup moved by (-15, -90, -45) mm: {r['pair_count']} intersecting "
      f"triangle pairs in {r['groups']} pairs of faces (findings)")
PY
echo
echo "mtcs serve is running: open $url and sign in as demo, password $password"
echo "(data in $data; Ctrl-C stops it; add people with: echo PASSWORD | $MTCS serve --data $data --add-user NAME --role reviewer)"
if [ "$check" = 1 ]; then exit 0; fi
wait $server
