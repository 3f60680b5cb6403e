// A file of comments only is no PRISM program: PRISM refuses it (at least one module).
// expect-error@1:1: the program declares no module: a PRISM program needs at least one
