// A solver that includes the case reader (a stage above its own): cmake/check_layers.cmake must refuse it
// (test Layers.IncludeAgainstTheOrderFailsTheCheck). Never compiled.
#include "lib/io/case.h"
