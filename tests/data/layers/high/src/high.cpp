#include "fapcast/high/high.hpp"
