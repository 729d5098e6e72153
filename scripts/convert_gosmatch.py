#!/usr/bin/env python3
"""Converts GOSMatch's KITTI 00 object centres into sgtllc node files, packed as one reproducible .tar.xz.

Input: GOSMatch's `00.tar.xz` (zhuyachen/GOSMatch @ 200fcbf9, MIT): `00/bow.txt` has one line per frame,
`n_vehicle,n_trunk,n_pole`, and `00/centroids/NNNNNN.txt` that frame's object centres (x y z, LiDAR frame), the
vehicles first, then the trunks, then the poles. Output: `objects/NNNNNN.txt` node files, one `x y z label` row
per object with the raw SemanticKITTI ids 10 (car), 71 (trunk) and 80 (pole), coordinates rounded to 1 mm.
The archive is byte-identical on every run (sorted names, fixed mtime/owner), so it can be re-made and diffed.
Only the Python standard library is used.

    scripts/convert_gosmatch.py GOSMATCH_00.tar.xz data/kitti/00/objects.tar.xz
"""
import io
import sys
import tarfile

LABELS = (10, 71, 80)  # bow.txt column order: vehicle, trunk, pole (GOSMatch's class order)


def convert(src_path, dst_path):
    # One sequential pass: seeking backwards in an xz stream would decompress it again from the start.
    with tarfile.open(src_path, "r|xz") as src:
        content = {m.name: src.extractfile(m).read().decode() for m in src if m.isfile()}
    bow = content["00/bow.txt"].split()
    files = []
    for frame, line in enumerate(bow):
        counts = [int(v) for v in line.split(",")]
        if len(counts) != 3 or min(counts) < 0:
            sys.exit(f"{src_path}: 00/bow.txt line {frame + 1}: expected n_vehicle,n_trunk,n_pole")
        name = f"00/centroids/{frame:06d}.txt"
        rows = [r.split() for r in content[name].splitlines() if r.strip()]
        if len(rows) != sum(counts) or any(len(r) != 3 for r in rows):
            sys.exit(f"{src_path}: {name}: {len(rows)} rows, bow.txt says {sum(counts)} (x y z each)")
        labels = [lab for lab, n in zip(LABELS, counts) for _ in range(n)]
        text = "".join(f"{float(x):.3f} {float(y):.3f} {float(z):.3f} {lab}\n"
                       for (x, y, z), lab in zip(rows, labels))
        files.append((f"objects/{frame:06d}.txt", text.encode()))
    with tarfile.open(dst_path, "w:xz", preset=9, format=tarfile.USTAR_FORMAT) as dst:
        for name, data in files:
            info = tarfile.TarInfo(name)
            info.size, info.mtime, info.mode = len(data), 0, 0o644
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            dst.addfile(info, io.BytesIO(data))
    print(f"{dst_path}: {len(files)} node files")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])
