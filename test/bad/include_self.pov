#include "include_self.pov"
