#!/bin/sh
# Prototype (issue 10), not part of tests/run.py: make a stick patch-test
# case from tutorials/contactPatchTest in <dir>:
#   makeStick.sh <dir> [ux] [uy] [lower|upper] [equal|stiffUpper] [stick|frictionless]
# The upper top is displaced by (ux, -uy), the lower bottom fixed, the
# sides (the left symmetry plane made a plain patch) carry the uniform
# shear traction (0, +-tau) with tau = ux/(0.5/G_lower + 0.5/G_upper)
# (nu = 0, G = E/2), and the slave has `friction stick;`. Exact (nu = 0,
# blocks in series): sigma_yy = -uy/(0.5/E_l + 0.5/E_u), sigma_xy = tau,
# sigma_xx = 0 in every cell. Then: cd <dir> && blockMesh &&
# solidContactFoam && python3 checkStick.py <dir> ux uy E_upper
set -e
root=$(cd "$(dirname "$0")/../../.." && pwd)
dst=$1; ux=${2:-0.01}; uy=${3:-0.01}; slave=${4:-lower}; materials=${5:-equal}; friction=${6:-stick}
rm -rf "$dst"; cp -r "$root/tutorials/contactPatchTest" "$dst"
cd "$dst"
if [ "$materials" = stiffUpper ]; then E2=1e9; else E2=1e6; fi
tau=$(python3 -c "print($ux/(0.5/0.5e6+0.5/(0.5*$E2)))")
sed -i "s|^#include.*materials/equal\"|#include \"materials/$materials\"|" constant/mechanicalProperties
if [ "$slave" = upper ]; then
  sed -i -e "/^[[:space:]]*lowerTop[[:space:]]*\$/,/}/s/\\\$slave;/\\\$master;/" -e "/^[[:space:]]*upperBottom[[:space:]]*\$/,/}/s/\\\$master;/\\\$slave;/" 0/D
fi
sed -i '/^    left$/,/}/s/type symmetryPlane;/type patch;/' system/blockMeshDict
python3 - "$ux" "$uy" "$tau" "$friction" <<'PY'
import sys,re
ux,uy,tau,fr=sys.argv[1:]
s=open('0/D').read()
s=s.replace("    method          lagrangeMultiplier;","    method          lagrangeMultiplier;\n    friction        %s;"%fr,1)
s=re.sub(r"upperTop\s*\{[^}]*\}", "upperTop\n    {\n        type fixedValue;\n        value uniform (%s -%s 0);\n    }"%(ux,uy), s)
s=re.sub(r"lowerBottom\s*\{[^}]*\}", "lowerBottom\n    {\n        type fixedValue;\n        value uniform (0 0 0);\n    }", s)
s=re.sub(r"    left\s*\{[^}]*\}", "    left\n    {\n        type solidTraction;\n        traction constant (0 -%s 0);\n        pressure constant 0;\n        value uniform (0 0 0);\n    }"%tau, s)
s=re.sub(r"    right\s*\{[^}]*\}", "    right\n    {\n        type solidTraction;\n        traction constant (0 %s 0);\n        pressure constant 0;\n        value uniform (0 0 0);\n    }"%tau, s)
open('0/D','w').write(s)
PY
grep -n "symmetryPlane" system/blockMeshDict || true
grep -n "include" constant/mechanicalProperties; grep -A3 "lowerTop$\|upperBottom$" 0/D
