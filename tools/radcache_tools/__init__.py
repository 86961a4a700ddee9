"""The measurement tools' library: what the scripts under tools/ share (a package, not a command).

  radcache     the one way to run radcache: the executable ($RADCACHE, else build/radcache of
               this checkout), a run that exits naming the command when it fails, a render that
               returns its --stats, the CPU seconds of the runs
  error        an image's error against a reference as `radcache compare` measures it: its
               figures, and the one relMSE the tools report (net of the reference's noise where
               compare knows that noise, else the plain relMSE)
  knobs        the methods and their quality knobs, read from `radcache render --list-knobs
               --json`, and the options each method's table declares (`radcache reference`)
  equal_time   every method rendered by the same --time budget against the shipped references
               (tools/bench/equal_time.py, tools/bench/auto.py)
  references   where a shipped scene's reference lies, and its records
  arguments    argument types and the options after `--`
  scene_files  scene.json and OBJ meshes as the scene writers read them

The scripts import it without editing sys.path: a script in tools/ finds it beside itself (Python
puts a script's folder first on its path), and each subfolder with scripts (tools/bench/,
tools/peers/mitsuba/, tools/peers/povray/) holds a link, radcache_tools, to this folder.
"""

import os

# The repository's root (through the links of the subfolders to this package).
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
