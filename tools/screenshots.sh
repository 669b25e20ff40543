#!/usr/bin/env bash
# ./pba screenshots: regenerates docs/images/LAB-SCENE.png from the labs themselves (under Xvfb
# without a display). Usage: tools/screenshots.sh ROOT BUILD_DIR
set -euo pipefail
root="$1"
build="$2"
mkdir -p "$root/docs/images"
run=()
[[ -z "${DISPLAY:-}" ]] && run=(bash "$root/tools/with_xvfb.sh" -s "-screen 0 1280x720x24")
# shellcheck source=tools/progress.sh
source "$root/tools/progress.sh"
count=0
total=0
for exe in "$build"/bin/pba-*; do total=$((total + $("$exe" --list-scenes | wc -l))); done
pba_progress_start
for exe in "$build"/bin/pba-*; do
  lab="${exe##*/pba-}"
  for scene in $("$exe" --list-scenes | awk '{print $1}'); do
    png="$root/docs/images/$lab-$scene.png"
    frames="${PBA_SCREENSHOT_FRAMES:-150}"
    # The oscillator's figure is its state at end_time (3 periods = 18.85 s): 19 s of frames.
    [[ "$lab-$scene" == particles-oscillator ]] && frames=1140
    "${run[@]}" "$exe" --scene "$scene" --frames "$frames" --screenshot "$png" >/dev/null
    count=$((count + 1))
    pba_progress screenshots "$count" "$total" "scenes"
  done
done
# The lecture-mode look, for the instructor guide.
if [[ -x "$build/bin/pba-hello" ]]; then
  "${run[@]}" "$build/bin/pba-hello" --scene spring --lecture --frames 150 --screenshot "$root/docs/images/hello-lecture.png" >/dev/null
  echo "wrote docs/images/hello-lecture.png"
  count=$((count + 1))
fi
# The spring ball after 8 s, its energy plot decayed (HELLO-5's figure in the workbook).
if [[ -x "$build/bin/pba-hello" ]]; then
  "${run[@]}" "$build/bin/pba-hello" --scene spring --frames 480 --screenshot "$root/docs/images/hello-spring-energy.png" >/dev/null
  echo "wrote docs/images/hello-spring-energy.png"
  count=$((count + 1))
fi
# The undamped stiff spring ball in frames of 0.1 s after 8 s: HELLO-4's substeps keep it stable (its figure).
if [[ -x "$build/bin/pba-hello" ]]; then
  "${run[@]}" "$build/bin/pba-hello" --scene spring --dt 0.1 --set stiffness=500 --set damping=0 --set drag=0 \
    --time-scale 4 --frames 120 --screenshot "$root/docs/images/hello-spring-substeps.png" >/dev/null
  echo "wrote docs/images/hello-spring-substeps.png"
  count=$((count + 1))
fi
# The cloth's bending (CLOTH-6) and box (CLOTH-7) figures of the workbook, after 4 s.
if [[ -x "$build/bin/pba-cloth" ]]; then
  "${run[@]}" "$build/bin/pba-cloth" --scene drape --frames 240 --screenshot "$root/docs/images/cloth-bending-drape.png" >/dev/null
  "${run[@]}" "$build/bin/pba-cloth" --scene tablecloth --frames 240 --screenshot "$root/docs/images/cloth-tablecloth-box.png" >/dev/null
  echo "wrote docs/images/cloth-bending-drape.png docs/images/cloth-tablecloth-box.png"
  count=$((count + 2))
fi
# The implicit cloth at k = 1e5 N/m, one step per frame (the hanging scene's preset 5; CLOTH-5's figure).
if [[ -x "$build/bin/pba-cloth" ]]; then
  "${run[@]}" "$build/bin/pba-cloth" --scene hanging --set solver=implicit --set substeps=1 --set stiffness=1e5 \
    --frames 150 --screenshot "$root/docs/images/cloth-hanging-implicit-stiff.png" >/dev/null
  echo "wrote docs/images/cloth-hanging-implicit-stiff.png"
  count=$((count + 1))
fi
# The adaptive integrator on the orbit after 10 s (PART-8's figure in the workbook).
if [[ -x "$build/bin/pba-particles" ]]; then
  "${run[@]}" "$build/bin/pba-particles" --scene orbit --integrator adaptive --frames 600 \
    --screenshot "$root/docs/images/particles-orbit-adaptive.png" >/dev/null
  echo "wrote docs/images/particles-orbit-adaptive.png"
  count=$((count + 1))
fi
# RK4 alone on the oscillator at its end time (PART-3) and position Verlet on the orbit after 10 s
# (PART-6), for the workbook.
if [[ -x "$build/bin/pba-particles" ]]; then
  "${run[@]}" "$build/bin/pba-particles" --scene oscillator --integrator rk4 --set only_selected=true --frames 1140 \
    --screenshot "$root/docs/images/particles-oscillator-rk4.png" >/dev/null
  "${run[@]}" "$build/bin/pba-particles" --scene orbit --integrator verlet --frames 600 \
    --screenshot "$root/docs/images/particles-orbit-verlet.png" >/dev/null
  echo "wrote docs/images/particles-oscillator-rk4.png docs/images/particles-orbit-verlet.png"
  count=$((count + 2))
fi
# The Jacobian view of the IK lab (heat map and singular values), for the workbook.
if [[ -x "$build/bin/pba-ik" ]]; then
  "${run[@]}" "$build/bin/pba-ik" --scene tree --set solver=dls --frames 150 --screenshot "$root/docs/images/ik-jacobian.png" >/dev/null
  echo "wrote docs/images/ik-jacobian.png"
  count=$((count + 1))
fi
# The chain scene under DLS (IK-4) and under FABRIK in the paper's setting (IK-5), for the workbook.
if [[ -x "$build/bin/pba-ik" ]]; then
  "${run[@]}" "$build/bin/pba-ik" --scene chain --set solver=dls --frames 150 --screenshot "$root/docs/images/ik-chain-dls.png" >/dev/null
  "${run[@]}" "$build/bin/pba-ik" --scene chain --set solver=fabrik --set joint=ball --set limits=0 --frames 150 \
    --screenshot "$root/docs/images/ik-chain-fabrik.png" >/dev/null
  echo "wrote docs/images/ik-chain-dls.png docs/images/ik-chain-fabrik.png"
  count=$((count + 2))
fi
# A skinned character (the mesh follows the solved skeleton).
if [[ -x "$build/bin/pba-ik" && -f /usr/share/assimp/models/X/Testwuson.X ]]; then
  "${run[@]}" "$build/bin/pba-ik" --scene character --skeleton /usr/share/assimp/models/X/Testwuson.X --frames 150 \
    --screenshot "$root/docs/images/ik-character-skinned.png" >/dev/null
  echo "wrote docs/images/ik-character-skinned.png"
  count=$((count + 1))
fi
# The expected-result figures of workbook chapters 4-7 (exercises COLL, RIGID, RAG and ANIM): a scene with the
# parameters and the number of frames (1/60 s each) its caption names.
exercise_figure() {
  local lab="$1" png="$2"
  shift 2
  [[ -x "$build/bin/pba-$lab" ]] || return 0
  "${run[@]}" "$build/bin/pba-$lab" "$@" --screenshot "$root/docs/images/$png" >/dev/null
  echo "wrote docs/images/$png"
  count=$((count + 1))
}
exercise_figure rigid rigid-stack-sap.png --scene stack --set broad_phase=sap --frames 120
exercise_figure rigid rigid-tumble-bouncy.png --scene tumble --set restitution=0.8 --set friction=0.3 --frames 150
exercise_figure rigid rigid-tumble-clay.png --scene tumble --set restitution=0 --set friction=0.8 --frames 90
exercise_figure ragdoll ragdoll-rag5-frames.png --scene boxes --frames 45
exercise_figure ragdoll ragdoll-rag6-joints.png --scene ball-chain --frames 60
exercise_figure animation animation-anim1-hermite.png --scene splines --set follow=hermite --set tension=0.8 \
  --set show_catmull_rom=false --set show_natural_cubic=false --set show_linear=false --frames 150
exercise_figure animation animation-anim2-catmull-rom.png --scene splines --set show_hermite=false \
  --set show_natural_cubic=false --set show_linear=false --frames 150
exercise_figure animation animation-anim4-run.png --scene secondary --set gait=run --frames 150
exercise_figure animation animation-anim5-squad.png --scene keyframes --set rotation=squad --frames 40
exercise_figure animation animation-anim6-blend.png --scene blend --frames 198
echo "screenshots: $count images in docs/images"
