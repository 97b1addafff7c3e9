// The scattering table shipped in Data/, loaded once per test program.
#ifndef ShippedTable_h
#define ShippedTable_h

#include "ScatteringTable.h"

#include <gtest/gtest.h>

inline const avs::ScatteringTable& Shipped()
{
  static avs::ScatteringTable table;
  static bool loaded = false;
  if (!loaded)
  {
    std::string error;
    loaded = table.Read(AVS_SOURCE_TABLE_PATH, &error);
    EXPECT_TRUE(loaded) << error;
  }
  return table;
}

#endif
