// Linked into every executable of a sanitizer build (FRUSTUM_SANITIZE, FRUSTUM_FUZZ): the
// sanitizers read their defaults from these functions (the environment still overrides them).
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_options();
extern "C" const char* __asan_default_options();

// CLN allocates a few bytes once for its own global tables and never frees them (not per input).
extern "C" const char* __lsan_default_suppressions() { return "leak:libcln.so\n"; }

// The CLI tests read the program's output; a suppression summary would corrupt it.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }

// A signal stays a signal, as without sanitizers: batch/isolate.hpp reports a child killed by
// SIGSEGV as crashed (ASan's own memory checks do not rely on SIGSEGV).
extern "C" const char* __asan_default_options() { return "handle_segv=0"; }
