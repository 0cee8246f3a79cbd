// Forwards to the public header: the library API and toyhost's own code use the same type.
#pragma once

#include <toyhost/Result.h>
