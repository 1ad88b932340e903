#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UBSan (build-fuzz/, clang; see
# tools/sanitized_build.sh) and runs it. Any memory error, leak or undefined behaviour aborts
# the test that caused it.
set -euo pipefail
cd "$(dirname "$0")/.."

. tools/sanitized_build.sh
cmake --build "$SANITIZED_BUILD" --parallel "$(nproc)" --target frustum_tests frustum
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Not repeated here (CI's 60 minutes): the benchmarks and soaks (label bench), the source checks
# (Source.*: Python and clang-format, no Frustum code runs) and the tests whose time is a browser's
# or TeX's (Typeset.*, *Browser.*: the pages they open come from the same Frustum code that the
# other tests run sanitized), the two scans of every student-facing text for English words and
# lecture file names (text searches over output the other tests produce sanitized;
# Language.NoEnglish…, …CitesNoLectureFile), the 36 random scenes drawn by the exact rasterizer (a
# large share of the sanitized pass; the certified frame and the exact rasterizer run sanitized in
# their other tests), and the tests whose length is repetition of paths other tests run sanitized
# once: the same files generated with 1 and with N jobs (Cli.Generate*WhateverJobs), a large scene
# drawn again with threads (RenderKind.ALargeScene…), every bundled variant's text and every shipped
# file read twice (TextLiteralsTest.EveryBundledVariant…, YamlDocument.OnePass…/AByteOrderMark…),
# and every subcommand's --help (Cli.EverySubcommandHasAnExample…), and the warnings' property test
# over 54 generated ill-conditioned problems of each numeric kind in four backends (the numeric
# paths it runs are the hard cases' and NumericPaths' paths, run sanitized there;
# ConditioningProperty.WarningsTell…) and the radical suite's check (exact solves on radicals, which
# the hard cases' exact signs run sanitized; NumericPaths.RadicalInputs…). Together they are a large
# share of the sanitized suite's time; the GCC suite runs all of them.
repeats='^(Source|Typeset|FeedbackBrowser|ServeBrowser|AuthorBrowser)\.'
repeats+='|^Language\.(NoEnglish[A-Za-z]*|StudentTextCitesNoLectureFile)$'
repeats+='|^CertifiedFrame\.RandomOrdinaryScenesEqualTheExactRasterizer$'
repeats+='|^Cli\.(Generate[A-Za-z]*WhateverJobs|EverySubcommandHasAnExampleAndPlainChoices)$'
repeats+='|^RenderKind\.ALargeSceneStreamedWithThreadsGivesTheFrameOfOneThread$'
repeats+='|^TextLiteralsTest\.EveryBundledVariantStatesItsDrawnValues$'
repeats+='|^YamlDocument\.(OnePassBuildsTheTreeYamlLoadBuildsForEveryShippedFile|AByteOrderMarkChangesNothing)$'
repeats+='|^ConditioningProperty\.WarningsTellTheDigitsActuallyKept$|^NumericPaths\.RadicalInputsAreSolvedExactly$'
ctest --test-dir "$SANITIZED_BUILD" --output-on-failure --parallel "$(nproc)" -LE bench -E "$repeats"
