#!/usr/bin/env python3
"""Writes the records of a reference render (radcache_tools/references.py says what and where):

  tools/references.py record STATS --scene SCENE_DIR --dest DIR --command "radcache render ..."
      [--git REVISION] [--date YYYY-MM-DD]
"""

import sys

from radcache_tools.references import main

if __name__ == "__main__":
    main(sys.argv[1:])
