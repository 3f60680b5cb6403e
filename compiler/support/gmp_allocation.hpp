#pragma once
// GMP that throws std::bad_alloc instead of aborting.
//
// GMP's own allocation functions print "GNU MP: Cannot allocate memory" and call abort()
// when malloc fails: under a memory budget (common/command_line/memory_budget.hpp) any large exact
// computation, ours or CGAL's, would crash the process instead of ending in main's
// "oasisc: error: out of memory". The functions installed here throw std::bad_alloc instead,
// as cvc5 and other C++ users of GMP do.
//
// GMP's manual calls unwinding out of an allocation function undefined: GMP does not clean up
// the temporaries of the operation in flight. That is acceptable here because the exception
// only ever ends the command (main catches it and exits); nothing resumes exact arithmetic
// after it. Unwinding through GMP's frames needs their unwind tables, which the x86-64 and
// AArch64 ABIs make the default (Debian's libgmp has .eh_frame).

namespace oasis {

// Installs the throwing functions. Call it first thing in main, before any GMP number exists
// (the functions free with std::free, so numbers made before would still be released right).
void make_gmp_throw_on_allocation_failure();

}  // namespace oasis
