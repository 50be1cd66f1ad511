"""One package per machine element: parameters, state layout, Problem, steady limit, Result."""
