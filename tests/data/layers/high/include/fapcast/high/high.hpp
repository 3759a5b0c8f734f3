#pragma once
#include "fapcast/low/low.hpp"
