#!/usr/bin/env python3
"""Compilation throughput, mxc against MaterialX as users script it, measured in one run.

    python3 tests/bench/compile_throughput.py [--build DIR] [--repeat N] [--jobs N] [--report FILE]

Two measurements, both whole processes with everything they load:

- One document: `mxc compile DOC -o DOC.spv` against MaterialX 1.39.5's Python generator
  (a process that imports MaterialX, loads its libraries, generates the Vulkan GLSL of every
  renderable element and writes the pixel stages) followed by `glslangValidator -V` on each
  pixel stage, the median of N runs for each of the comparison documents
  (cli/comparison-documents.txt).
- A batch: every document of ../shared/corpus (materialx/examples, openpbr-presets) in one
  process: `mxc compile FOLDERS -o DIR -j JOBS` against one MaterialX process over all of them
  followed by glslangValidator on every pixel stage, JOBS at a time (as `xargs -P` would).
  Reported per material (each side divides by the materials it compiled); the median of
  max(3, N) runs a side, the sides alternated.

MaterialX runs with the options of materialx_compare.py (one directional light, no environment
lighting, no transparency, linear output), from the venv that script makes (DIR/materialx-venv).
Writes generated/reports/throughput.md.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import materialx_compare  # noqa: E402  (the venv, the document list, the generator options)

ROOT = materialx_compare.ROOT
SHARED = materialx_compare.SHARED
BATCH_FOLDERS = ["materialx/examples", "openpbr-presets"]

# The MaterialX side, run by the venv's interpreter: every renderable element of each document
# given, its pixel stage written to OUT/<n>.frag. Prints the number of shaders written.
GENERATOR = r'''
import sys
from pathlib import Path
sys.path.insert(0, sys.argv[1])
from materialx_compare import materialx_context
import MaterialX as mx
import MaterialX.PyMaterialXGenGlsl as mx_glsl
import MaterialX.PyMaterialXGenShader as mx_gen
out = Path(sys.argv[2])
library = mx.createDocument()
search_path = mx.getDefaultDataSearchPath()
mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search_path, library)
written = 0
for path in sys.argv[3:]:
    doc = mx.createDocument()
    mx.readFromXmlFile(doc, path)
    mx.flattenFilenames(doc, mx.FileSearchPath(str(Path(path).parent)))
    doc.setDataLibrary(library)
    for element in mx_gen.findRenderableElements(doc):
        generator = mx_glsl.VkShaderGenerator.create()
        cms = mx_gen.DefaultColorManagementSystem.create(generator.getTarget())
        cms.loadLibrary(library)
        generator.setColorManagementSystem(cms)
        context = materialx_context(generator, library, search_path)
        shader = generator.generate(element.getName(), element, context)
        pixel = shader.getSourceCode(mx_gen.PIXEL_STAGE)
        if "u_refractionTwoSided" in pixel and "bool u_refractionTwoSided" not in pixel:
            version, rest = pixel.split("\n", 1)  # see materialx_compare.py
            pixel = version + "\nconst bool u_refractionTwoSided = false;\n" + rest
        (out / f"{written}.frag").write_text(pixel)
        written += 1
print(written)
'''


def corpus_documents():
    docs = []
    for folder in BATCH_FOLDERS:
        docs += sorted(str(p) for p in (SHARED / "corpus" / folder).rglob("*.mtlx"))
    return docs


def materialx_run(python: Path, documents, jobs: int):
    """One MaterialX process over `documents`, then glslangValidator on each pixel stage, `jobs`
    at a time. Returns (seconds, shaders compiled to SPIR-V)."""
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch)
        start = time.perf_counter()
        here = str(Path(__file__).resolve().parent)
        generated = subprocess.run([str(python), "-c", GENERATOR, here, str(out)] + list(documents), check=True,
                                   capture_output=True, text=True)
        count = int(generated.stdout.strip().splitlines()[-1])

        def validate(i):
            stage = out / f"{i}.frag"
            r = subprocess.run(["glslangValidator", "-V", "--target-env", "vulkan1.1", str(stage), "-o",
                                str(out / f"{i}.spv")], capture_output=True, text=True)
            return r.returncode == 0

        with ThreadPoolExecutor(max_workers=jobs) as pool:
            ok = sum(pool.map(validate, range(count)))
        return time.perf_counter() - start, ok


def mxc_run(mxc: Path, arguments, jobs: int):
    """`mxc compile ARGUMENTS -o DIR -j JOBS` as one process. Returns (seconds, materials)."""
    with tempfile.TemporaryDirectory() as scratch:
        start = time.perf_counter()
        command = [str(mxc), "compile"] + list(arguments) + ["-o", str(Path(scratch) / "out"), "-j", str(jobs)]
        r = subprocess.run(command, capture_output=True, text=True)
        seconds = time.perf_counter() - start
        if r.returncode != 0:
            sys.exit(f"compile_throughput: {' '.join(command)} failed:\n{r.stderr}")
        # One fragment stage per material (each also has its vertex stage, *.vert.spv, beside it).
        materials = sum(1 for p in (Path(scratch) / "out").rglob("*.spv") if not p.name.endswith(".vert.spv"))
        return seconds, materials


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=Path, default=ROOT / "build")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--report", type=Path, default=ROOT / "generated" / "reports" / "throughput.md")
    args = parser.parse_args()
    mxc = args.build / "mxc"
    python = materialx_compare.venv_python(args.build)

    rows = []
    for relative in materialx_compare.DEFAULT_DOCUMENTS:
        doc = str(SHARED / "corpus" / relative)
        theirs, ours = [], []
        for _ in range(args.repeat):  # alternated, as the batch below
            theirs.append(materialx_run(python, [doc], 1)[0])
            ours.append(mxc_run(mxc, [doc], 1)[0])
        rows.append((Path(relative).stem, statistics.median(theirs), statistics.median(ours)))
        print(f"{rows[-1][0]}: MaterialX {1000 * rows[-1][1]:.0f} ms, mxc {1000 * rows[-1][2]:.0f} ms", file=sys.stderr)

    documents = corpus_documents()
    # At least three runs a side, alternated run by run, so that a drift of the machine's speed
    # (seen here: a tenth over an hour) weighs on both sides alike.
    their_batch, our_batch = [], []
    for _ in range(max(3, args.repeat)):
        their_batch.append(materialx_run(python, documents, args.jobs))
        our_batch.append(mxc_run(mxc, [str(SHARED / "corpus" / f) for f in BATCH_FOLDERS], args.jobs))
    their_seconds = statistics.median(t for t, _ in their_batch)
    our_seconds = statistics.median(t for t, _ in our_batch)
    their_count = their_batch[0][1]
    our_count = our_batch[0][1]
    their_per = their_seconds / max(their_count, 1)
    our_per = our_seconds / max(our_count, 1)

    ratios = [t / o for _, t, o in rows]
    lines = [
        "# Compilation throughput: mxc against MaterialX",
        "",
        f"Written by `python3 tests/bench/compile_throughput.py --repeat {args.repeat} --jobs {args.jobs}` "
        f"({time.strftime('%Y-%m-%d')}, {os.cpu_count()} cores). Whole processes, everything they load included: "
        "mxc from the document to validated SPIR-V; MaterialX "
        f"{materialx_compare.MATERIALX_VERSION}'s Python generator writing the pixel stages, then "
        "`glslangValidator -V` on each (as a user scripts it). Medians.",
        "",
        "## One document",
        "",
        "| document | MaterialX + glslangValidator (ms) | mxc compile (ms) | MaterialX / mxc |",
        "|---|---:|---:|---:|",
    ]
    for name, theirs, ours in rows:
        lines.append(f"| {name} | {1000 * theirs:.0f} | {1000 * ours:.0f} | {theirs / ours:.1f} |")
    lines += [
        "",
        f"Median ratio {statistics.median(ratios):.1f}x (smallest {min(ratios):.1f}x); the target is 3x.",
        "",
        "## A batch: every corpus document in one process",
        "",
        f"{len(documents)} documents ({', '.join(BATCH_FOLDERS)}), {args.jobs} at a time on each side.",
        "",
        "| | shaders | total (s) | per material (ms) |",
        "|---|---:|---:|---:|",
        f"| MaterialX, then glslangValidator per pixel stage | {their_count} | {their_seconds:.2f} | {1000 * their_per:.1f} |",
        f"| `mxc compile FOLDERS -o DIR -j {args.jobs}` | {our_count} | {our_seconds:.2f} | {1000 * our_per:.1f} |",
        "",
        f"Per material, mxc is {their_per / our_per:.1f}x faster; the target is 20x.",
        "",
    ]
    args.report.parent.mkdir(parents=True, exist_ok=True)
    args.report.write_text("\n".join(lines))
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
