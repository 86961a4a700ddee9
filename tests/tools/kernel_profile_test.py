#!/usr/bin/env python3
"""tools/bench/kernel_profile.py: its reading of perf's report and annotation (kernel objects
only, each instruction's share to the inlined function above it), and end to end where perf can
sample here: a path-traced Cornell box's kernel samples add up to all of them and include Arvo's
spherical-triangle sampler, which vanishes from the profile when the kernels are built to sample
every light triangle by area (the function no longer runs). Run by CTest with $RADCACHE set."""

import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "bench"))
import kernel_profile  # noqa: E402

SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp",
                       "kernel_profile_test")
SCENE = os.path.join(ROOT, "scenes", "cornell-box", "scene.json")

REPORT = """
# Overhead  Shared Object        Symbol
    54.27%  path_trace_pass.so   [.] rc_path_radiance
    14.89%  path_trace_pass.so   [.] rc_intersect_wide_leaves
     2.96%  ld-linux-x86-64.so.2 [.] do_lookup_x
     1.35%  libLLVM-15.so.1      [.] 0x000000000196afb0
     0.31%  [kernel.kallsyms]    [k] _raw_spin_unlock_irqrestore
"""

ANNOTATE = """
 Percent |	Source code & Disassembly of path_trace_pass.so
         :
    1.00 :   6e50:   vmovss %xmm0,%xmm1,%xmm1
         : 331  rc_light_triangle_solid_angle():
    0.01 :   9a49:   vucomiss %xmm17,%xmm1
    4.84 :   9ada:   vsubps 0x200(%rsp),%xmm13,%xmm1
         : 50   rc_path_radiance():
    0.15 :   9ae3:   vxorps %xmm2,%xmm2,%xmm2
         : 182  rc_light_triangle_solid_angle():
    2.00 :   9ae7:   vcmpeqps %xmm2,%xmm1,%xmm2
"""


def perf_can_sample():
    """Whether perf records a process here (installed, and the kernel lets it sample)."""
    if shutil.which("perf") is None:
        return False
    probe = os.path.join(SCRATCH, "probe.data")
    result = subprocess.run(["perf", "record", "-q", "-o", probe, "true"], capture_output=True)
    return result.returncode == 0


class Reading(unittest.TestCase):
    def test_only_kernel_objects_count(self):
        rows = kernel_profile.kernel_symbols(REPORT)
        self.assertEqual([r[2] for r in rows], ["rc_path_radiance", "rc_intersect_wide_leaves"])
        self.assertAlmostEqual(rows[0][0], 54.27)

    def test_instructions_go_to_the_function_above_them(self):
        shares = kernel_profile.function_shares(ANNOTATE, "rc_path_radiance")
        self.assertAlmostEqual(shares["rc_light_triangle_solid_angle"], 0.01 + 4.84 + 2.00)
        self.assertAlmostEqual(shares["rc_path_radiance"], 1.00 + 0.15)
        self.assertEqual(len(shares), 2)


@unittest.skipUnless(os.path.exists(kernel_profile.radcache.executable()), "radcache is not built")
class EndToEnd(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        if not perf_can_sample():
            raise unittest.SkipTest("perf cannot sample on this machine (missing, or "
                                    "/proc/sys/kernel/perf_event_paranoid forbids it)")

    def profile(self, name, kernel_dir):
        command = ["render", SCENE, "--method", "pt", "--width", "96", "--height", "96",
                   "--spp", "8", "--quiet", "-o", os.path.join(SCRATCH, name + ".exr"),
                   "--kernel-dir", kernel_dir]
        return kernel_profile.profile(command, os.path.join(SCRATCH, name + ".data"))

    def test_a_function_that_does_not_run_is_not_in_the_profile(self):
        shipped = self.profile("shipped", os.path.join(ROOT, "kernels"))
        self.assertAlmostEqual(sum(shipped.values()), 100.0, delta=0.5)
        self.assertGreater(shipped.get("rc_sample_spherical_triangle", 0.0), 0.2)
        self.assertGreater(shipped.get("rc_philox4x32_10", 0.0), 0.2)
        # The same kernels, every light triangle sampled by area (kernels/common/light.h).
        area_only = os.path.join(SCRATCH, "kernels-area-only")
        shutil.copytree(os.path.join(ROOT, "kernels"), area_only)
        light = os.path.join(area_only, "common", "light.h")
        with open(light) as f:
            text = f.read()
        self.assertIn("#define RC_SOLID_ANGLE_SAMPLING_MIN 1e-3f", text)
        with open(light, "w") as f:
            f.write(text.replace("#define RC_SOLID_ANGLE_SAMPLING_MIN 1e-3f",
                                 "#define RC_SOLID_ANGLE_SAMPLING_MIN 1e30f"))
        by_area = self.profile("area-only", area_only)
        self.assertAlmostEqual(sum(by_area.values()), 100.0, delta=0.5)
        self.assertEqual(by_area.get("rc_sample_spherical_triangle", 0.0), 0.0)
        self.assertGreater(by_area.get("rc_philox4x32_10", 0.0), 0.2)


if __name__ == "__main__":
    unittest.main()
