# Command-line checks of the particles lab (issue 4): one test a line. Metrics are read from the JSON that
# --metrics writes (pretty-printed, one key a line), so grep and awk suffice.
set(pa_exe $<TARGET_FILE:pba-particles>)
set(pa_work "${CMAKE_BINARY_DIR}/smoke/particles-cli")
file(MAKE_DIRECTORY "${pa_work}")
# value KEY FILE: the number after "KEY": in FILE.
set(pa_value "value() { grep -m1 \"\\\"$1\\\": \" \"$2\" | sed 's/.*: //; s/,$//'; }")
# An explicit method (midpoint: not an exercise) on the stiff beam blows up and the instability guard
# pauses with its message and exit code 3; implicit Euler on the same beam stays stable (|energy_drift| < 1 %). Depends on the spring force
# (PART-4: with its stub the beam falls apart under either method), hence the tag (DESIGN.md §5).
add_test(NAME PART_4_lab.particles.stiff-spring-explicit-pauses-with-the-guards-message-implicit-stays COMMAND bash -c "${pa_value}; \"$0\" --headless --scene stiff-spring --integrator midpoint --seconds 2 --metrics '${pa_work}/stiff.json' 2>'${pa_work}/stiff.err'; rc=$?; [[ $rc -eq 3 ]] || { echo \"exit code $rc, expected 3 (paused by the guard)\"; exit 1; }; grep -q '\"paused_by_guard\": true' '${pa_work}/stiff.json' && grep -q 'energy grew from .* (runaway)' '${pa_work}/stiff.err' && grep -q '\"guard_message\": \"Paused: energy grew' '${pa_work}/stiff.json' && \"$0\" --headless --scene stiff-spring --integrator implicit-euler --seconds 2 --metrics '${pa_work}/stiff-implicit.json' && grep -q '\"paused_by_guard\": false' '${pa_work}/stiff-implicit.json' && awk -v d=$(value energy_drift '${pa_work}/stiff-implicit.json') 'BEGIN { exit !(d < 0.01 && d > -0.01) }'" ${pa_exe})
# Every --integrator name works on a ParticleSystem scene, and is reported back.
add_test(NAME lab.particles.every-integrator-name-runs COMMAND bash -c "for k in euler symplectic-euler midpoint rk4 verlet velocity-verlet implicit-euler adaptive; do \"$0\" --headless --scene bouncing --integrator $k --frames 30 --metrics '${pa_work}/int.json' || exit 1; grep -q \"\\\"integrator\\\": \\\"$k\\\"\" '${pa_work}/int.json' || { echo \"$k not reported\"; exit 1; }; done" ${pa_exe})
add_test(NAME lab.particles.unknown-integrator-exits-2 COMMAND bash -c "\"$0\" --headless --integrator nope 2>'${pa_work}/nope.err'; rc=$?; cat '${pa_work}/nope.err'; [[ $rc -eq 2 && $(wc -l <'${pa_work}/nope.err') -eq 1 ]] && grep -q \"unknown value 'nope'\" '${pa_work}/nope.err'" ${pa_exe})
# A million particles: 3 frames run with the full pool; after 2.5 s (longer than the shortest lifetime) it is full.
add_test(NAME lab.particles.fountain-million-runs COMMAND bash -c "\"$0\" --headless --scene fountain --particles 1000000 --frames 3 --metrics - | grep -q '\"pool\": 1000000' && \"$0\" --headless --scene fountain --particles 1000000 --seconds 2.5 --metrics - | grep -q '\"particles\": 1000000'" ${pa_exe})
# The metric keys of the issue, in every scene; the oscillator's error too.
add_test(NAME lab.particles.metric-keys-of-the-issue COMMAND bash -c "for s in $(\"$0\" --list-scenes | awk '{print $1}'); do \"$0\" --headless --scene $s --frames 10 --metrics '${pa_work}/keys.json' || exit 1; for key in integrator particles energy energy_drift particle_updates_per_s; do grep -q \"^    \\\"$key\\\": \" '${pa_work}/keys.json' || { echo \"$s: no $key\"; exit 1; }; done; done; \"$0\" --headless --scene oscillator --frames 10 --metrics - | grep -q '^    \"error\": '" ${pa_exe})
# Oscillator: Lobb's experiment at end_time = 3 periods, h = 0.1: Euler's error far above RK4's, energy ≈ 6.5×.
# Depends on explicit Euler and RK4 (PART-1, PART-3), hence the tag.
add_test(NAME PART_1_lab.particles.oscillator-euler-error-exceeds-rk4-at-end-time COMMAND bash -c "${pa_value}; \"$0\" --headless --scene oscillator --seconds 20 --metrics '${pa_work}/osc.json' || exit 1; t=$(value time_s '${pa_work}/osc.json'); eu=$(value error_euler '${pa_work}/osc.json'); rk=$(value error_rk4 '${pa_work}/osc.json'); e=$(value energy_euler '${pa_work}/osc.json'); echo \"t=$t euler=$eu rk4=$rk E_euler=$e\"; awk -v t=$t -v eu=$eu -v rk=$rk -v e=$e 'BEGIN { exit !((t - 6 * atan2(0, -1))^2 < 1e-18 && eu > 1000 * rk && e / 0.5 > 6.4 && e / 0.5 < 6.6) }'" ${pa_exe})
set_tests_properties(PART_4_lab.particles.stiff-spring-explicit-pauses-with-the-guards-message-implicit-stays
                     lab.particles.every-integrator-name-runs lab.particles.unknown-integrator-exits-2 lab.particles.fountain-million-runs
                     lab.particles.metric-keys-of-the-issue PART_1_lab.particles.oscillator-euler-error-exceeds-rk4-at-end-time
                     PROPERTIES LABELS "labs" TIMEOUT 180)
