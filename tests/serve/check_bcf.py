"""Checks a BCF file mtcs serve exported: every file valid against buildingSMART's BCF-XML 3.0
schemas (xmllint), one folder per item with its markup, each viewpoint's camera the saved one in
metres (the meshes' millimetres / 1000), and the markup's comments pointing at existing .bcfv files.
Usage: python3 check_bcf.py FILE.bcf SCHEMAS_DIR ITEMS CAMERA_X,CAMERA_Y,CAMERA_Z(mm)
Exit 0: passed; 1: failed (the reasons printed)."""
import subprocess, sys, tempfile, zipfile, os
import xml.etree.ElementTree as ET

bcf, schemas, items, camera = sys.argv[1], sys.argv[2], int(sys.argv[3]), [float(v) for v in sys.argv[4].split(",")]
failures = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok: failures.append(what)

with tempfile.TemporaryDirectory() as out:
    with zipfile.ZipFile(bcf) as z:
        names = z.namelist()
        z.extractall(out)
    schema_of = {"bcf.version": "version.xsd", "extensions.xml": "extensions.xsd"}
    for name in names:
        xsd = schema_of.get(name) or ("markup.xsd" if name.endswith("markup.bcf") else "visinfo.xsd" if name.endswith(".bcfv") else None)
        check(xsd is not None, f"{name}: a BCF file")
        if not xsd: continue
        r = subprocess.run(["xmllint", "--noout", "--schema", os.path.join(schemas, xsd), os.path.join(out, name)],
                           capture_output=True, text=True)
        check(r.returncode == 0, f"{name} is valid against {xsd}" + ("" if r.returncode == 0 else ": " + r.stderr.strip()))
    folders = sorted({n.split("/")[0] for n in names if "/" in n})
    check(len(folders) == items, f"{len(folders)} item folders, {items} items")
    seen_camera = False
    for folder in folders:
        markup = ET.parse(os.path.join(out, folder, "markup.bcf")).getroot()
        topic = markup.find("Topic")
        check(topic.get("Guid") == folder, f"{folder}: the folder is the topic's GUID")
        for ref in topic.iter("ViewPoint"):
            file = os.path.join(out, folder, ref.find("Viewpoint").text)
            check(os.path.exists(file), f"{folder}: its viewpoint {ref.find('Viewpoint').text} is in the file")
            info = ET.parse(file).getroot()
            p = info.find("PerspectiveCamera/CameraViewPoint")
            xyz = [float(p.find(a).text) for a in "XYZ"]
            if all(abs(v - 0.001 * c) < 1e-12 for v, c in zip(xyz, camera)): seen_camera = True
    check(seen_camera, f"a viewpoint's camera is at {camera} mm, in metres")
if failures:
    print(f"FAILED: {len(failures)} check(s)")
    sys.exit(1)
print("PASSED")
