"""Build hook: compile slidespin's numerical core ahead of time (numba ``pycc``).

Without it, the first ``simulate`` in a new environment JIT-compiles the integrator and the
wrench kernel (~30 s of CPU); with it, nothing is compiled for the demo, an ellipse or a
footprint (other entries still compile on first use and are cached by numba). The compiled
module is the same numba source (see ``src/slidespin/_aot_build.py``), and it is used
only while its sources are unchanged (``src/slidespin/_aot.py``).

- editable install (``pip install -e .``): written into ``src/slidespin/`` and
  compiled for this machine's CPU (``host``), like the JIT;
- wheel: compiled for a ``generic`` CPU of the platform and added to the wheel, which is then
  platform-specific.

The compile runs in a subprocess of the build environment (numba and numpy are the hook's
build dependencies). A failure (no C compiler, an unsupported numba) is reported and skipped:
the package then JIT-compiles on first use, as before. ``SLIDESPIN_AOT=0`` skips the step.
"""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

from hatchling.builders.hooks.plugin.interface import BuildHookInterface

_ROOT = Path(__file__).resolve().parent
_SRC = _ROOT / "src"
_PACKAGE = _SRC / "slidespin"


def _compile(output_dir: Path, target_cpu: str) -> list[Path]:
    env = dict(os.environ)
    env.pop("NUMBA_DISABLE_JIT", None)
    # the sources are put first on the path by the child itself (pip's isolated build
    # environment rewrites PYTHONPATH); its JIT cache stays out of the tree
    code = (
        "import sys; sys.path.insert(0, sys.argv[1]); "
        "from slidespin._aot_build import build; build(sys.argv[2], sys.argv[3])"
    )
    with tempfile.TemporaryDirectory(prefix="slidespin-aot-cache-") as cache:
        env["NUMBA_CACHE_DIR"] = cache
        subprocess.run(
            [sys.executable, "-c", code, str(_SRC), str(output_dir), target_cpu],
            check=True,
            env=env,
            cwd=str(_ROOT),
        )
    suffix = sysconfig.get_config_var("EXT_SUFFIX") or ".so"
    return [output_dir / ("_aot_core" + suffix), output_dir / "_aot_core.json"]


class AheadOfTimeCore(BuildHookInterface):
    PLUGIN_NAME = "custom"

    def initialize(self, version: str, build_data: dict) -> None:
        if self.target_name != "wheel" or os.environ.get("SLIDESPIN_AOT", "1").strip() == "0":
            return
        editable = version == "editable"
        sys.stderr.write(
            "slidespin: compiling the numerical core ahead of time (about a minute)...\n"
        )
        try:
            if editable:
                _compile(_PACKAGE, "host")
                return
            out = Path(tempfile.mkdtemp(prefix="slidespin-aot-"))
            files = _compile(out, os.environ.get("SLIDESPIN_AOT_CPU", "generic"))
        except (subprocess.CalledProcessError, OSError) as err:
            sys.stderr.write(
                f"slidespin: the ahead-of-time core was not built ({err}); the numerical "
                "kernels will be compiled on first use instead\n"
            )
            return
        for f in files:
            build_data["force_include"][str(f)] = f"slidespin/{f.name}"
        build_data["pure_python"] = False
        build_data["infer_tag"] = True
