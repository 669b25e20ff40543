# shellcheck shell=bash
# The ctest names (a regular expression) of the tests that only this repository has: the checks of the
# exercise machinery itself, the marking check, the house style. Sourced by tools/check_student_release.sh
# and tools/check_golden_tolerance.sh, which run the hand-out's suite without them.
# shellcheck disable=SC2034  # used by the scripts that source it
not_in_handout='^(exercises\.(student-release|catalog|golden-tolerance)|coursework\.mark|repository\.(formatted|builds-with-clang14))$'
