#!/usr/bin/env python3
"""A report page with a 100k-triangle part and 60 bores, for the issue-13 load target: the data
block of a page `mtcs report` wrote is replaced by a synthetic one (a torus of 100 000
triangles as the cavity mesh, 60 bores in 4 circuits under it); the page's code is unchanged.
Usage: large_page.py IN.html OUT.html"""
import base64, json, math, re, struct, sys

src, out = sys.argv[1], sys.argv[2]
html = open(src).read()
m = re.search(r'(<script type="application/json" id="report-data">)(.*?)(</script>)', html, re.S)
data = json.loads(m.group(2))

# Torus, n x k quads -> 2nk triangles = 100 000 (n = 250, k = 200), centred in a 300 x 200 x 120 block.
n, k, R, r = 250, 200, 80.0, 12.0
pos, idx = [], []
for i in range(n):
    u = 2 * math.pi * i / n
    for j in range(k):
        v = 2 * math.pi * j / k
        pos += [150 + (R + r * math.cos(v)) * math.cos(u), 100 + (R + r * math.cos(v)) * math.sin(u) * 0.8, 90 + r * math.sin(v)]
for i in range(n):
    for j in range(k):
        a, b, c, d = i * k + j, ((i + 1) % n) * k + j, ((i + 1) % n) * k + (j + 1) % k, i * k + (j + 1) % k
        idx += [a, b, c, a, c, d]
mesh = {"positions": base64.b64encode(struct.pack('<%df' % len(pos), *pos)).decode(),
        "indices": base64.b64encode(struct.pack('<%dI' % len(idx), *idx)).decode(), "triangles": len(idx) // 3}
data["scene"]["cavity"] = {"mesh": mesh}

def bore(c, s, p0, p1, d=8):
    return {"name": f"c{c}.b{s}", "circuit": c, "segment": s, "p0": p0, "p1": p1, "diameter": d, "flow": [p0, p1],
            "length": math.dist(p0, p1), "entry_face": "-y", "entry_angle": 0, "plugged": False, "through": False, "dead_end": 0}
for member in data["members"]:
    bores, ports = [], []
    for c in range(4):
        z = 40 + 10 * c
        for s in range(15):
            x = 20 + 17.5 * s + 2 * c
            bores.append(bore(c, s, [x, 0, z], [x, 195, z]))
        ports.append({"circuit": c, "inlet": bores[-15]["p0"], "outlet": bores[-1]["p0"]})
    member["layout"] = {"bores": bores, "ports": ports, "circuits": 4, "plugs": 0}
data["temperature"] = None
text = json.dumps(data).replace("</", "<\\/")
open(out, "w").write(html[:m.start(2)] + text + html[m.end(2):])
print(f"{out}: {len(idx) // 3} part triangles, 60 bores, {len(html[:m.start(2)]) + len(text) + len(html[m.end(2):])} bytes")
