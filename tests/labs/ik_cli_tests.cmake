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
set_tests_properties(lab.ik.flag-order-does-not-pick-the-scene lab.ik.skeleton-malformed-exits-2 lab.ik.skeleton-missing-exits-2 lab.ik.effector-unknown-exits-2
                     lab.ik.skeleton-cmu-bvh-runs lab.ik.skeleton-batch-runs PROPERTIES LABELS "labs" TIMEOUT 120 SKIP_RETURN_CODE 77)
