/* Header compile test: abi/tests/CMakeLists.txt compiles this file once per
 * public ABI header (PN_TEST_HEADER) and per language standard, as C and as
 * C++, with -Wall -Wextra -pedantic -Werror. Each header must be
 * self-contained and warning-free on its own. */
#include PN_TEST_HEADER

int pn_header_compile_probe(void);
int pn_header_compile_probe(void) { return PN_ABI_MAJOR; }
