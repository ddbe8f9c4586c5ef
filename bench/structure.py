"""A real structure for the benchmark scenes: the adenylate kinase system of
MDAnalysis's test data (4AKE chain A in a box of water and ions, OPLS-AA;
47,681 atoms), fetched from PyPI once (`pip download` of the MDAnalysisTests
source distribution, about 60 MB) and its PDB file kept in
target/bench-data/. Not in the repository: it is that package's data.

    python3 bench/structure.py        # fetch (if needed) and print the path
"""
import os
import subprocess
import sys
import tarfile
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = "MDAnalysisTests==2.11.0"
MEMBER = "mdanalysistests-2.11.0/MDAnalysisTests/data/adk_oplsaa.pdb"
ATOMS = 47681

# Van der Waals radii (Å) and colours of the elements the system holds.
ELEMENT = {
    "H": (1.20, (0.9, 0.9, 0.9)),
    "C": (1.70, (0.55, 0.55, 0.55)),
    "N": (1.55, (0.19, 0.31, 0.97)),
    "O": (1.52, (1.0, 0.05, 0.05)),
    "S": (1.80, (1.0, 1.0, 0.19)),
    "NA": (2.27, (0.67, 0.36, 0.95)),
    "CL": (1.75, (0.12, 0.94, 0.12)),
}


def data_dir():
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    return os.path.join(target, "bench-data")


def adk_path():
    """The PDB file, fetched and extracted on first use."""
    path = os.path.join(data_dir(), "adk_oplsaa.pdb")
    if os.path.exists(path):
        return path
    os.makedirs(data_dir(), exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, "-m", "pip", "download", "--quiet", "--no-deps",
                        "--no-binary", ":all:", PACKAGE, "-d", tmp], check=True)
        sdist = next(os.path.join(tmp, f) for f in os.listdir(tmp) if f.endswith(".tar.gz"))
        with tarfile.open(sdist) as tar:
            data = tar.extractfile(MEMBER).read()
    with open(path + ".part", "wb") as f:
        f.write(data)
    os.replace(path + ".part", path)
    return path


def element(name, residue):
    """The element of a PDB atom without an element column: the ions by
    residue name, everything else by the first letter of the atom name."""
    residue = residue.strip().upper()
    if residue in ("NA", "SOD"):
        return "NA"
    if residue in ("CL", "CLA"):
        return "CL"
    letters = "".join(c for c in name if c.isalpha()).upper()
    return letters[:1]


def atoms(path):
    """[(x, y, z), radius, colour] of every ATOM/HETATM record of the first
    model."""
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith("ENDMDL"):
                break
            if not line.startswith(("ATOM", "HETATM")):
                continue
            xyz = (float(line[30:38]), float(line[38:46]), float(line[46:54]))
            radius, colour = ELEMENT.get(element(line[12:16], line[17:21]), ELEMENT["C"])
            out.append((xyz, radius, colour))
    return out


if __name__ == "__main__":
    p = adk_path()
    n = len(atoms(p))
    print(p, f"({n} atoms)")
    sys.exit(0 if n == ATOMS else 1)
