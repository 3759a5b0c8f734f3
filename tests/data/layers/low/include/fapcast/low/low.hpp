#pragma once
// Wrong on purpose: the bottom layer reaches up.
#include "fapcast/high/high.hpp"
