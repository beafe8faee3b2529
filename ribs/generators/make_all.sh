#!/bin/sh
# Regenerates every generated micro-geometry RIB in ribs/ (run from anywhere).
set -e
cd "$(dirname "$0")/.."
python3 generators/brushed_metal.py > brushed_metal.rib
python3 generators/grass.py --model v1 --texturename grass_v1.pm > grass_v1.rib
python3 generators/grass.py --model grass --texturename grass.pm > grass.rib
python3 generators/grass.py --model mowed --texturename grass_mowed.pm > grass_mowed.rib
python3 generators/grass.py --model grass --kd 0.5 --ks 0.5 --texturename grass_microbrdf_a.pm \
    --comment "fig. 5.19 (a): micro BRDF kd 0.5, ks 0.5" > grass_microbrdf_a.rib
python3 generators/grass.py --model grass --kd 0.3 --ks 0.7 --texturename grass_microbrdf_b.pm \
    --comment "fig. 5.19 (b): micro BRDF kd 0.3, ks 0.7" > grass_microbrdf_b.rib
python3 generators/grass.py --model grass --periodic --texturename grass_periodic.pm \
    --comment "periodic tile: the same blades wrapped at the tile edges" > grass_periodic.rib
python3 generators/grass.py --model v1 --leaf --texturename grass_v1_leaf.pm \
    --comment "blades with leaf optics (docs/brdflight.md)" > grass_v1_leaf.rib
python3 generators/grass.py --model grass --leaf --texturename grass_leaf.pm \
    --comment "blades with leaf optics (docs/brdflight.md)" > grass_leaf.rib
python3 generators/grass.py --model mowed --leaf --texturename grass_mowed_leaf.pm \
    --comment "blades with leaf optics (docs/brdflight.md)" > grass_mowed_leaf.rib
