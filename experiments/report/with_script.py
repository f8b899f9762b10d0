#!/usr/bin/env python3
"""A report page with its page script swapped for another (e.g. src/report/assets/report.js as
edited), so that page code can be compared on the same data without rebuilding mtcs.
Usage: with_script.py IN.html SCRIPT.js OUT.html"""
import sys

src, script, out = sys.argv[1:4]
html = open(src).read()
start = html.rindex('<script type="module">') + len('<script type="module">')
end = html.index('</script>', start)
open(out, 'w').write(html[:start] + open(script).read() + html[end:])
