# Sourced by piglit-fetch.sh, piglit-run.sh and piglit-mesa.sh: the folders
# of piglit's spec/ tree the scripts fetch and run, grouped into sets.
#
#   legacy  GLSL 1.10 and 1.20 (what .ci/run measures)
#   glsl3   GLSL 1.30, 1.40, 1.50, 3.30, the extensions those versions
#           absorbed that have compiler tests of their own (issue 30),
#           GL_ARB_arrays_of_arrays (GLSL 4.30's, offered on every context),
#           GL_ARB_shading_language_packing and GL_ARB_texture_cube_map_array
#           (GLSL 4.20's and 4.00's, offered on 3.3 contexts)
#   all     both
#
# A folder NAME is tests/spec/NAME/ and generated_tests/spec/NAME/ in the
# package (either may be missing: arb_shading_language_packing's tests are
# all generated), and the tests piglit names spec@NAME@... in its results.

# piglit_fetched DATA FOLDER: whether FOLDER's tests are in the extracted
# tree DATA (usr/lib/x86_64-linux-gnu/piglit).
piglit_fetched() {
    [ -d "$1/tests/spec/$2" ] || [ -d "$1/generated_tests/spec/$2" ]
}

piglit_legacy_folders="glsl-1.10 glsl-1.20"
piglit_glsl3_folders="glsl-1.30 glsl-1.40 glsl-1.50 glsl-3.30 arb_geometry_shader4 arb_explicit_attrib_location arb_uniform_buffer_object arb_arrays_of_arrays arb_shading_language_packing arb_texture_cube_map_array arb_shading_language_420pack arb_compute_shader arb_shader_storage_buffer_object arb_tessellation_shader"

# piglit_folders SET: prints the folders of SET on one line; fails (status
# 1, nothing printed) for an unknown set.
piglit_folders() {
    case "$1" in
        legacy) echo "$piglit_legacy_folders" ;;
        glsl3) echo "$piglit_glsl3_folders" ;;
        all) echo "$piglit_legacy_folders $piglit_glsl3_folders" ;;
        *) return 1 ;;
    esac
}

# piglit_tag SUITE SET: the name of a run's results, counts and
# expected-failures files: SUITE for legacy (the names CI has always used),
# SUITE-SET otherwise.
piglit_tag() {
    if [ "$2" = legacy ]; then echo "$1"; else echo "$1-$2"; fi
}

# piglit_filters FOLDER...: piglit's `-t REGEX` arguments selecting those
# folders' tests, one word each (dots escaped).
piglit_filters() {
    local f
    for f in "$@"; do
        printf -- '-t\nspec@%s@\n' "${f//./\\.}"
    done
}

# piglit_prefixes FOLDER...: the folders as piglit's test-name prefixes,
# comma-separated, for piglit_compare.py --folders.
piglit_prefixes() {
    local f out=
    for f in "$@"; do out="${out:+$out,}spec@$f@"; done
    echo "$out"
}
