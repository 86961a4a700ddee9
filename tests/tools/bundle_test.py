#!/usr/bin/env python3
"""tools/bundle.sh: the bundle's executable, run through its launcher, loads every
shared library from the bundle except the C library's own (ldd with the launcher's library path:
each resolves inside the bundle or to the allowed glibc set, none is missing); the launcher
lists the devices and renders a bundled scene; the scenes come without their references; a
missing build is refused. Run by CTest with $RADCACHE set to the built executable."""

import os
import re
import shutil
import subprocess
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BUNDLE = os.path.join(ROOT, "tools", "bundle.sh")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "bundle_test")
# The C library's own libraries, which stay the machine's (written here, not read from the script).
GLIBC = {"linux-vdso.so.1", "ld-linux-x86-64.so.2", "libc.so.6", "libm.so.6", "libpthread.so.0",
         "libdl.so.2", "librt.so.1", "libresolv.so.2", "libutil.so.1", "libanl.so.1"}


class BundleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        result = subprocess.run(["bash", BUNDLE, "--dir-only", os.path.dirname(RADCACHE), SCRATCH],
                                capture_output=True, text=True)
        assert result.returncode == 0, result.stdout + result.stderr
        names = [n for n in os.listdir(SCRATCH) if n.startswith("radcache-")]
        assert len(names) == 1, names
        cls.bundle = os.path.join(SCRATCH, names[0])

    def test_name_has_the_version_and_platform(self):
        self.assertRegex(os.path.basename(self.bundle), r"^radcache-\d+\.\d+\.\d+-linux-x86_64$")

    def test_every_library_resolves_inside_the_bundle_or_to_glibc(self):
        lib = os.path.join(self.bundle, "lib")
        env = dict(os.environ, LD_LIBRARY_PATH=lib)
        result = subprocess.run(["ldd", os.path.join(self.bundle, "bin", "radcache")],
                                capture_output=True, text=True, env=env)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("not found", result.stdout)
        outside = []
        count = 0
        for line in result.stdout.splitlines():
            found = re.match(r"^\s*(\S+)(?: => (\S+))? \(0x", line)
            self.assertIsNotNone(found, line)
            soname, path = found.group(1), found.group(2)
            count += 1
            name = os.path.basename(soname)
            if path is not None and os.path.realpath(path).startswith(os.path.realpath(lib) + "/"):
                continue
            if name not in GLIBC:
                outside.append(line.strip())
        self.assertEqual(outside, [])
        self.assertGreater(count, len(GLIBC))
        # The OpenCL ICD loader is one of the bundle's own.
        self.assertTrue(os.path.isfile(os.path.join(lib, "libOpenCL.so.1")))

    def test_launcher_lists_devices_and_renders_a_bundled_scene(self):
        launcher = os.path.join(self.bundle, "radcache")
        env = dict(os.environ)
        env.pop("LD_LIBRARY_PATH", None)
        devices = subprocess.run([launcher, "devices"], capture_output=True, text=True, env=env)
        self.assertEqual(devices.returncode, 0, devices.stdout + devices.stderr)
        output = os.path.join(SCRATCH, "cornell.png")
        render = subprocess.run(
            [launcher, "render", os.path.join(self.bundle, "scenes", "cornell-box", "scene.json"),
             "--width", "16", "--height", "16", "--spp", "1", "-o", output, "--quiet"],
            capture_output=True, text=True, env=env)
        self.assertEqual(render.returncode, 0, render.stdout + render.stderr)
        self.assertGreater(os.path.getsize(output), 0)

    def test_scenes_come_without_references(self):
        scenes = os.path.join(self.bundle, "scenes")
        self.assertTrue(os.path.isfile(os.path.join(scenes, "cornell-box", "scene.json")))
        for dirpath, dirnames, filenames in os.walk(scenes):
            self.assertNotIn("reference", dirnames, dirpath)
            self.assertEqual([f for f in filenames if f.startswith("reference") and
                              f.endswith(".exr")], [], dirpath)

    def test_refuses_a_missing_build(self):
        result = subprocess.run(["bash", BUNDLE, "--dir-only", os.path.join(SCRATCH, "nothing"),
                                 os.path.join(SCRATCH, "out")], capture_output=True, text=True)
        self.assertEqual(result.returncode, 2)
        self.assertIn("build first", result.stderr)


if __name__ == "__main__":
    unittest.main()
