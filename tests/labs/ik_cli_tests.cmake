# Command-line checks of the IK lab's imported skeletons (--skeleton, --effectors): one test a line.
# A bad skeleton file or effector name exits 2 with one line naming the file; any Assimp skeleton runs.
set(ik_exe $<TARGET_FILE:pba-ik>)
set(ik_work "${CMAKE_BINARY_DIR}/smoke/ik-cli")
file(MAKE_DIRECTORY "${ik_work}")
add_test(NAME lab.ik.skeleton-malformed-exits-2 COMMAND bash -c "printf 'HIERARCHY\\nROOT Hips\\n{ OFFSET 0 oops\\n' > '${ik_work}/bad.bvh'; \"$0\" --headless --skeleton '${ik_work}/bad.bvh' 2>'${ik_work}/bad.err'; rc=$?; cat '${ik_work}/bad.err'; [[ $rc -eq 2 && $(wc -l <'${ik_work}/bad.err') -eq 1 ]] && grep -q 'pba-ik: skeleton: .*bad.bvh' '${ik_work}/bad.err'" ${ik_exe})
add_test(NAME lab.ik.skeleton-missing-exits-2 COMMAND bash -c "\"$0\" --headless --skeleton '${ik_work}/no-such.fbx' 2>'${ik_work}/missing.err'; rc=$?; cat '${ik_work}/missing.err'; [[ $rc -eq 2 ]] && grep -q 'skeleton: .*no-such.fbx' '${ik_work}/missing.err'" ${ik_exe})
add_test(NAME lab.ik.effector-unknown-exits-2 COMMAND bash -c "\"$0\" --headless --scene character --effectors LeftHand,Nope 2>'${ik_work}/eff.err'; rc=$?; cat '${ik_work}/eff.err'; [[ $rc -eq 2 ]] && grep -q \"effectors: no joint named 'Nope' in .*humanoid.bvh (joints: Hips, Spine\" '${ik_work}/eff.err'" ${ik_exe})
add_test(NAME lab.ik.skeleton-cmu-bvh-runs COMMAND bash -c "f=/usr/share/assimp/models/BVH/01_01.bvh; [[ -f $f ]] || exit 77; \"$0\" --headless --skeleton $f --effectors LeftHand,RightFoot --frames 30 --metrics '${ik_work}/cmu.json' && grep -q '\"effectors\": 2' '${ik_work}/cmu.json' && grep -q '\"finite\": true' '${ik_work}/cmu.json'" ${ik_exe})
add_test(NAME lab.ik.skeleton-batch-runs COMMAND bash -c "\"$0\" --headless --skeleton resources/models/humanoid.bvh --effectors LeftHand,RightFoot --solver dls --targets 20 --seed 3 --metrics - | grep -q '\"effectors\": 2'" ${ik_exe})
# The scene follows the flags' priorities, not their order: --targets (batch) > --skeleton (character) > --solver.
add_test(NAME lab.ik.flag-order-does-not-pick-the-scene COMMAND bash -c "\"$0\" --headless --targets 5 --skeleton resources/models/humanoid.bvh --metrics - | grep -q '\"scene\": \"batch\"' && \"$0\" --headless --skeleton resources/models/humanoid.bvh --solver ccd --frames 5 --metrics - | grep -q '\"scene\": \"character\"'" ${ik_exe})
# Batch mode: the issue's key names; a skeleton reports its own joint count; what batch cannot measure
# exits 2 with one line (analytic beyond 2 links, a skeleton without effectors or moving joints).
add_test(NAME lab.ik.batch-skeleton-reports-the-file COMMAND bash -c "\"$0\" --headless --skeleton resources/models/humanoid.bvh --effectors LeftHand,RightFoot --solver dls --targets 5 --metrics '${ik_work}/skel.json' && grep -q '\"joint\": \"skeleton\"' '${ik_work}/skel.json' && grep -q '\"solve_us_median\"' '${ik_work}/skel.json' && grep -q '\"solve_us_p95\"' '${ik_work}/skel.json' && python3 -c \"import json,sys; d=json.load(open(sys.argv[1]))['ik']; sys.exit(0 if d['links'] == d['joints'] > 2 else 1)\" '${ik_work}/skel.json'" ${ik_exe})
add_test(NAME lab.ik.batch-analytic-beyond-2-links-exits-2 COMMAND bash -c "\"$0\" --headless --solver analytic --links 5 --targets 10 --metrics - 2>'${ik_work}/ana.err'; rc=$?; cat '${ik_work}/ana.err'; [[ $rc -eq 2 && $(wc -l <'${ik_work}/ana.err') -eq 1 ]] && grep -q -- '--solver analytic applies to 1 or 2 links, got --links 5' '${ik_work}/ana.err'" ${ik_exe})
add_test(NAME lab.ik.batch-skeleton-without-effectors-exits-2 COMMAND bash -c "printf 'HIERARCHY\\nROOT Hips\\n{\\n OFFSET 0 0 0\\n CHANNELS 3 Zrotation Xrotation Yrotation\\n}\\nMOTION\\nFrames: 1\\nFrame Time: 0.033\\n0 0 0\\n' > '${ik_work}/lone.bvh'; \"$0\" --headless --skeleton '${ik_work}/lone.bvh' --targets 10 --metrics - 2>'${ik_work}/lone.err'; rc=$?; cat '${ik_work}/lone.err'; [[ $rc -eq 2 && $(wc -l <'${ik_work}/lone.err') -eq 1 ]] && grep -q 'pba-ik: skeleton: .*lone.bvh: no joint can move' '${ik_work}/lone.err'" ${ik_exe})
# Every goal of batch mode is reachable (forward kinematics of a random pose): analytic IK on 1 and 2
# links, hinge and ball, must reach all of them. The ball joints turn by IK-1's rotation, hence the
# tag (it fails against the stub); limits are off, since the clamp is IK-6's exercise.
add_test(NAME IK_1_AnalyticBatch.ReachesEveryGoalOfOneAndTwoLinkChains COMMAND bash -c "for a in '1 hinge' '1 ball' '2 hinge' '2 ball'; do set -- $a; \"$0\" --headless --solver analytic --links $1 --joint $2 --set limits=false --targets 500 --seed 1 --metrics - | grep -q '\"success_rate\": 1.0' || { echo \"analytic $1 $2 misses goals\"; exit 1; }; done" ${ik_exe})
# The determinism check ignores timings by their unit word (solve_us_median), nothing else.
add_test(NAME lab.ik.determinism-check-ignores-timing-keys COMMAND bash -c "echo '{\"ik\": {\"solve_us_median\": 1.0, \"fabrik_solve_us\": 2, \"success_rate\": 1.0}, \"step_ms\": {\"max\": 1}}' > '${ik_work}/a.json'; echo '{\"ik\": {\"solve_us_median\": 9.0, \"fabrik_solve_us\": 7, \"success_rate\": 1.0}, \"step_ms\": {\"max\": 5}}' > '${ik_work}/b.json'; echo '{\"ik\": {\"solve_us_median\": 1.0, \"fabrik_solve_us\": 2, \"success_rate\": 0.5}, \"step_ms\": {\"max\": 1}}' > '${ik_work}/c.json'; \"$0\" same '${ik_work}/a.json' '${ik_work}/b.json' && ! \"$0\" same '${ik_work}/a.json' '${ik_work}/c.json'" $<TARGET_FILE:pba_lab_check>)
# Every IK solver setting the command line reaches is checked at its boundary: exit 2 and one line
# naming the option (zero iteration caps, tolerance <= 0, negative damping, non-finite values, unknown
# names), in the chain scene and in batch mode.
add_test(NAME lab.ik.solver-settings-out-of-range-exit-2 COMMAND bash -c "check() { \"$0\" --headless --frames 1 \"$@\" --metrics /dev/null 2>'${ik_work}/opt.err'; rc=$?; [[ $rc -eq 2 && $(wc -l <'${ik_work}/opt.err') -eq 1 ]] && grep -q -- \"$want\" '${ik_work}/opt.err' || { echo \"$* -> rc $rc: $(cat '${ik_work}/opt.err')\"; exit 1; }; }; \
  want='--max-iterations:' check --scene chain --max-iterations 0; want='--tolerance:' check --scene chain --tolerance 0; \
  want='--tolerance:' check --scene chain --tolerance nan; want='--set damping:' check --scene chain --set damping=-1; \
  want='--set damping:' check --scene chain --set damping=inf; want='--set cutoff:' check --scene chain --set cutoff=0.9; \
  want='--set gradient_step:' check --scene chain --set gradient_step=0; want='--set stall_iterations:' check --scene chain --set stall_iterations=-1; \
  want='--set restarts:' check --scene chain --set restarts=-1; want='--set max_joint_step:' check --scene chain --set max_joint_step=-1; \
  want='--set time_cap:' check --scene chain --set time_cap=nan; want='--set jacobian:' check --scene chain --set jacobian=exact; \
  want='--set solver:' check --scene chain --set solver=newton; want='--set line_search:' check --scene chain --set line_search=wolfe; \
  want='--targets:' check --targets 0; want='--max-iterations:' check --targets 5 --max-iterations 0; \
  want='--tolerance:' check --targets 5 --tolerance -1e-4; want='--set restarts:' check --targets 5 --set restarts=1000" ${ik_exe})
# Batch mode reports the method as published (no restarts) and with the stall recovery separately;
# with restarts=0 the two runs are one. (That restarts help is IK-6's test: they matter with limits.)
add_test(NAME lab.ik.batch-reports-success-with-and-without-restarts COMMAND bash -c "\"$0\" --headless --solver pinv --links 10 --joint hinge --targets 100 --seed 1 --metrics '${ik_work}/restarts.json' && \"$0\" --headless --solver pinv --links 10 --joint hinge --targets 100 --seed 1 --set restarts=0 --metrics '${ik_work}/plain.json' && python3 -c \"import json,sys; a=json.load(open(sys.argv[1]))['ik']; b=json.load(open(sys.argv[2]))['ik']; ok = a['restarts'] == 10 and b['restarts'] == 0 and 0 <= a['success_rate_no_restarts'] <= 1 and 0 <= a['success_rate'] <= 1 and a['success_rate_no_restarts'] == b['success_rate_no_restarts'] == b['success_rate'] and b['iterations_mean_no_restarts'] == b['iterations_mean']; print(a, b); sys.exit(0 if ok else 1)\" '${ik_work}/restarts.json' '${ik_work}/plain.json'" ${ik_exe})
set_tests_properties(lab.ik.solver-settings-out-of-range-exit-2 lab.ik.batch-reports-success-with-and-without-restarts PROPERTIES LABELS "labs" TIMEOUT 120)
set_tests_properties(lab.ik.flag-order-does-not-pick-the-scene lab.ik.skeleton-malformed-exits-2 lab.ik.skeleton-missing-exits-2 lab.ik.effector-unknown-exits-2
                     lab.ik.skeleton-cmu-bvh-runs lab.ik.skeleton-batch-runs lab.ik.batch-skeleton-reports-the-file
                     lab.ik.batch-analytic-beyond-2-links-exits-2 lab.ik.batch-skeleton-without-effectors-exits-2
                     IK_1_AnalyticBatch.ReachesEveryGoalOfOneAndTwoLinkChains lab.ik.determinism-check-ignores-timing-keys
                     PROPERTIES LABELS "labs" TIMEOUT 120 SKIP_RETURN_CODE 77)
# --pose-json (app/pose_json.h): the file's joints are the solved pose, checked from outside. Each goal's
# joint lies as far from its goal as the solver's own residual says (the largest distance is the metric
# "residual"), within 1 mm when the solve succeeded; every bone keeps the length it has at rest (frame 1).
add_test(NAME lab.ik.pose-json-puts-the-effectors-on-their-goals COMMAND bash -c "for s in character two-bone chain; do \"$0\" --headless --scene $s --frames 1 --pose-json '${ik_work}/rest-'$s.json || exit 1; \"$0\" --headless --scene $s --frames 90 --pose-json '${ik_work}/pose-'$s.json --metrics '${ik_work}/pose-'$s-metrics.json || exit 1; python3 '${CMAKE_CURRENT_SOURCE_DIR}/check_pose_json.py' '${ik_work}/rest-'$s.json '${ik_work}/pose-'$s.json '${ik_work}/pose-'$s-metrics.json || exit 1; done" ${ik_exe})
# A scene without a skeleton refuses --pose-json before it runs: exit 2, one line naming the option.
add_test(NAME lab.ik.pose-json-without-a-skeleton-exits-2 COMMAND bash -c "\"$0\" --headless --scene comparison --frames 2 --pose-json '${ik_work}/none.json' 2>'${ik_work}/none.err'; rc=$?; cat '${ik_work}/none.err'; [[ $rc -eq 2 && $(wc -l <'${ik_work}/none.err') -eq 1 ]] && grep -q -- \"--pose-json: scene 'comparison' has no skeleton\" '${ik_work}/none.err'" ${ik_exe})
set_tests_properties(lab.ik.pose-json-puts-the-effectors-on-their-goals lab.ik.pose-json-without-a-skeleton-exits-2 PROPERTIES LABELS "labs" TIMEOUT 120)
