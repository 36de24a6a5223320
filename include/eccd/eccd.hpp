#pragma once
// eccd's one public header: `#include <eccd/eccd.hpp>`, link eccd::eccd.
// Everything a program needs (namespace eccd) comes from the API layer, api/.
#include "api/solve.hpp"
#include "api/static_status.hpp"
#include "api/certify.hpp"
#include "api/judge.hpp"
#include "api/separate.hpp"
