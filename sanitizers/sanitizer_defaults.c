// SPDX-License-Identifier: Apache-2.0
/* Default options of the AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer runtimes
 * for fgr's sanitizer build (FGR_SANITIZE). The runtimes look these functions up in the
 * executable at start-up. */

/* Stop at the first report (the build also has -fno-sanitize-recover=all) and exit with 86, which
 * fgr itself never uses, so a report can never pass for fgr's exit code 1 (failure) or 2 (usage)
 * in a test that expects one of those. */
#define FGR_SANITIZER_COMMON "halt_on_error=1:exitcode=86"

const char* __asan_default_options(void);
const char* __ubsan_default_options(void);
const char* __lsan_default_options(void);

const char* __asan_default_options(void) { return FGR_SANITIZER_COMMON ":detect_leaks=1"; }

const char* __ubsan_default_options(void) { return FGR_SANITIZER_COMMON ":print_stacktrace=1"; }

/* Third-party leaks only; see lsan.supp for each and why. A suppressed leak must leave no trace:
 * LeakSanitizer's table of the suppressions it used would otherwise be appended to stderr at exit,
 * where fgr's one-line errors are checked. */
/* use_tls=0: LeakSanitizer's tracer crashed ("Tracer caught signal 11", "LeakSanitizer has
 * encountered a fatal error", exit 86 with no report) while reading the thread-local storage of
 * the threads PoCL leaves at exit, in the same tests every run (PathTracer, EnvironmentTest).
 * Without thread-local storage as roots, a block only TLS points to would be reported as a leak,
 * never missed, so the check stays strict. */
const char* __lsan_default_options(void) {
    return FGR_SANITIZER_COMMON
        ":use_tls=0:print_suppressions=0:suppressions=" FGR_LSAN_SUPPRESSIONS;
}
