# Compile time of translation units, gcc against clang: each file's command from
# build-asan/compile_commands.json, run once with its own compiler and once with clang++.
# Usage (from the checkout): python3 experiments/ci/compile_time.py src/thermal/line_sink_setup.cpp ...
import json, os, shlex, subprocess, sys, time
cc=json.load(open('build-asan/compile_commands.json'))
want=sys.argv[1:]
for e in cc:
    f=os.path.relpath(e['file'])
    if f not in want: continue
    args=shlex.split(e['command'])
    i=args.index('-o'); args[i+1]='/tmp/tu_test.o'
    for comp in ['gcc','clang']:
        a=list(args)
        if comp=='clang': a[0]='clang++'; a.insert(1,'-Wno-unknown-warning-option')
        t=time.time(); r=subprocess.run(a,cwd=e['directory'],capture_output=True,text=True); dt=time.time()-t
        print(f"{comp:6s} {dt:6.1f} s rc={r.returncode} {f}", (r.stderr[:300] if r.returncode else ''), flush=True)
