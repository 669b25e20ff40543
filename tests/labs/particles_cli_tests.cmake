# Command-line checks of the particles lab (issue 4): one test a line. Metrics are read from the JSON that
# --metrics writes (pretty-printed, one key a line), so grep and awk suffice.
set(pa_exe $<TARGET_FILE:pba-particles>)
set(pa_work "${CMAKE_BINARY_DIR}/smoke/particles-cli")
file(MAKE_DIRECTORY "${pa_work}")
# value KEY FILE: the number after "KEY": in FILE.
set(pa_value "value() { grep -m1 \"\\\"$1\\\": \" \"$2\" | sed 's/.*: //; s/,$//'; }")
# An explicit method (velocity Verlet: not an exercise) on the stiff beam blows up and the instability guard
# pauses with its message and exit code 3; implicit Euler on the same beam stays stable, converges (CG within its
# cap and tolerance) and settles: at rest, having dissipated exactly the spring energy it stored (Clapeyron's
# theorem: dissipated/stored = 1 within 1 %; the beam's E₀ is almost all gravitational potential, so energy_drift
# would say nothing). Depends on the spring force (PART-4: with its stub nothing is stored), hence the tag
# (docs/architecture.md §5).
add_test(NAME PART_4_lab.particles.stiff-spring-explicit-pauses-with-the-guards-message-implicit-stays COMMAND bash -c "${pa_value}; \"$0\" --headless --scene stiff-spring --integrator velocity-verlet --seconds 2 --metrics '${pa_work}/stiff.json' 2>'${pa_work}/stiff.err'; rc=$?; [[ $rc -eq 3 ]] || { echo \"exit code $rc, expected 3 (paused by the guard)\"; exit 1; }; grep -q '\"paused_by_guard\": true' '${pa_work}/stiff.json' && grep -q 'energy grew from .* (runaway)' '${pa_work}/stiff.err' && grep -q '\"guard_message\": \"Paused: energy grew' '${pa_work}/stiff.json' && \"$0\" --headless --scene stiff-spring --integrator implicit-euler --seconds 2 --metrics '${pa_work}/stiff-implicit.json' && grep -q '\"paused_by_guard\": false' '${pa_work}/stiff-implicit.json' && grep -q '\"cg_cap_hit\": false' '${pa_work}/stiff-implicit.json' && awk -v d=$(value dissipated_J '${pa_work}/stiff-implicit.json') -v u=$(value spring_energy_J '${pa_work}/stiff-implicit.json') -v k=$(value kinetic_energy_J '${pa_work}/stiff-implicit.json') 'BEGIN { exit !(u > 1e-3 && (d / u - 1)^2 < 1e-4 && k < 1e-6 * u) }'" ${pa_exe})
# Every --integrator name works on a ParticleSystem scene, and is reported back.
add_test(NAME lab.particles.every-integrator-name-runs COMMAND bash -c "for k in euler symplectic-euler midpoint rk4 verlet velocity-verlet implicit-euler adaptive; do \"$0\" --headless --scene bouncing --integrator $k --frames 30 --metrics '${pa_work}/int.json' || exit 1; grep -q \"\\\"integrator\\\": \\\"$k\\\"\" '${pa_work}/int.json' || { echo \"$k not reported\"; exit 1; }; done" ${pa_exe})
add_test(NAME lab.particles.unknown-integrator-exits-2 COMMAND bash -c "\"$0\" --headless --integrator nope 2>'${pa_work}/nope.err'; rc=$?; cat '${pa_work}/nope.err'; [[ $rc -eq 2 && $(wc -l <'${pa_work}/nope.err') -eq 1 ]] && grep -q \"unknown value 'nope'\" '${pa_work}/nope.err'" ${pa_exe})
# A million particles: 3 frames run with the full pool; after 2.5 s (longer than the shortest lifetime) it is full.
add_test(NAME lab.particles.fountain-million-runs COMMAND bash -c "\"$0\" --headless --scene fountain --particles 1000000 --frames 3 --metrics - | grep -q '\"pool\": 1000000' && \"$0\" --headless --scene fountain --particles 1000000 --seconds 2.5 --metrics - | grep -q '\"particles\": 1000000'" ${pa_exe})
# The metric keys of the issue, in every scene; the oscillator's error too.
add_test(NAME lab.particles.metric-keys-of-the-issue COMMAND bash -c "for s in $(\"$0\" --list-scenes | awk '{print $1}'); do \"$0\" --headless --scene $s --frames 10 --metrics '${pa_work}/keys.json' || { [[ $? -eq 3 ]] && ! grep -q '\"not_implemented\": \\[\\]' '${pa_work}/keys.json'; } || exit 1; for key in integrator particles energy energy_drift particle_updates_per_s; do grep -q \"^    \\\"$key\\\": \" '${pa_work}/keys.json' || { echo \"$s: no $key\"; exit 1; }; done; done; \"$0\" --headless --scene oscillator --frames 10 --metrics - | grep -q '^    \"error\": '" ${pa_exe})
# Oscillator: Lobb's experiment at end_time = 3 periods, h = 0.1 (188 steps of h and one of 6π − 18.8): the
# methods stop exactly at 6π, and each method's energy is E₀ times its per-step factor (z = ωh) over those
# steps: explicit Euler (1 + z²), ≈ 6.5× (PART-1); RK4 1 − z⁶/72 + z⁸/576 (PART-3). One test per exercise,
# each stepping only its own method (only_selected), so that no other exercise's code runs.
add_test(NAME PART_1_lab.particles.oscillator-euler-energy-grows-by-its-factor-to-end-time COMMAND bash -c "${pa_value}; \"$0\" --headless --scene oscillator --integrator euler --set only_selected=true --seconds 20 --metrics '${pa_work}/osc-euler.json' || exit 1; t=$(value time_s '${pa_work}/osc-euler.json'); e=$(value energy_euler '${pa_work}/osc-euler.json'); echo \"t=$t E_euler=$e\"; awk -v t=$t -v e=$e 'BEGIN { pi = atan2(0, -1); last = 6 * pi - 18.8; f = 0.5 * (1 + last * last); for (i = 0; i < 188; ++i) f *= 1.01; exit !((t - 6 * pi)^2 < 1e-18 && (e / f - 1)^2 < 1e-18 && e / 0.5 > 6.4) }'" ${pa_exe})
add_test(NAME PART_3_lab.particles.oscillator-rk4-energy-decays-by-its-factor-to-end-time COMMAND bash -c "${pa_value}; \"$0\" --headless --scene oscillator --integrator rk4 --set only_selected=true --seconds 20 --metrics '${pa_work}/osc-rk4.json' || exit 1; t=$(value time_s '${pa_work}/osc-rk4.json'); e=$(value energy_rk4 '${pa_work}/osc-rk4.json'); r=$(value error_rk4 '${pa_work}/osc-rk4.json'); echo \"t=$t E_rk4=$e error_rk4=$r\"; awk -v t=$t -v e=$e -v r=$r 'BEGIN { pi = atan2(0, -1); z = 6 * pi - 18.8; f = 0.5 * (1 - z^6 / 72 + z^8 / 576); g = 1 - 0.1^6 / 72 + 0.1^8 / 576; for (i = 0; i < 188; ++i) f *= g; exit !((t - 6 * pi)^2 < 1e-18 && (e / f - 1)^2 < 1e-24 && e < 0.5 && r > 0 && r < 1e-4) }'" ${pa_exe})
set_tests_properties(PART_4_lab.particles.stiff-spring-explicit-pauses-with-the-guards-message-implicit-stays
                     lab.particles.every-integrator-name-runs lab.particles.unknown-integrator-exits-2 lab.particles.fountain-million-runs
                     lab.particles.metric-keys-of-the-issue PART_1_lab.particles.oscillator-euler-energy-grows-by-its-factor-to-end-time
                     PART_3_lab.particles.oscillator-rk4-energy-decays-by-its-factor-to-end-time
                     PROPERTIES LABELS "labs" TIMEOUT 180)
