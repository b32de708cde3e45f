# Cost functor and loss tests (paper Eqs. 8, 9, 10, 14): autodiff Jacobians
# against numeric differentiation, hand-computed residuals, small solves.
# All autodiff instantiations live in one TU (cost_functors_test.cc) because
# they compile slowly.
edgefit_add_test(costs_test
  SOURCES
    costs/cost_functors_test.cc
    costs/losses_test.cc
  LIBS edgefit::costs)
