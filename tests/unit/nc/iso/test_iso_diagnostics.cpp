#include "IsoTestSupport.h"

#include <gtest/gtest.h>
