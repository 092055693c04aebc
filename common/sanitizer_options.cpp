// Built into every program of the sanitizer build (GRAINMESH_SANITIZE): the options the
// sanitizers read at start, so `ctest`, a test's child `grainmesh` and the fuzz targets
// all run alike without environment variables.
extern "C" {

// fontconfig (reached through cairo's text) keeps its configuration until exit by design;
// the suppression is not reported (its statistics on stderr would break a refusal's one
// line).
const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }
const char* __lsan_default_options() { return "print_suppressions=0"; }

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

}
