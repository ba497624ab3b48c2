// The codecs of codecs.hpp in a file built with -Os (ROBOWIRE_OPTIMIZE_SIZE 1,
// ROBOWIRE_ARRAY_LOOPS 1 by default).
#define MIXED_MODES_FILE size_file
#include "codecs.hpp"
