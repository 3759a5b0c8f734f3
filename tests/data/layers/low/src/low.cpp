#include "fapcast/low/low.hpp"
