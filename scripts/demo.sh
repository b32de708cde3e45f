#!/usr/bin/env bash
# Installs what is missing, builds edgefit (Release) and runs it on the
# bundled data. Until the fit exists, it shows what edgefit reads: the bundled
# scans with their estimated lattice, and the bundled and real robot models.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh build/release Release -DEDGEFIT_BUILD_TESTS=OFF -- edgefit >/dev/null
edgefit=build/release/tools/edgefit

echo "== edgefit info --scan=assets/samples/two_scans.ptx"
"$edgefit" info --scan=assets/samples/two_scans.ptx
echo
echo "== edgefit info --urdf=assets/models/balancer_arm.urdf"
"$edgefit" info --urdf=assets/models/balancer_arm.urdf
robots=../shared/robots
if [[ -d $robots/kuka_kr150r3100_2 && -d $robots/weld_gun_x16005_botrail ]]; then
  echo
  echo "== edgefit info --urdf=KUKA KR 150 R3100 --attach=weld gun@tool0"
  "$edgefit" info --urdf=$robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf \
    --attach=$robots/weld_gun_x16005_botrail/weld_gun_x16005_botrail.urdf@tool0
fi
