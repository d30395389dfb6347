// SPDX-License-Identifier: GPL-2.0-or-later
// The contact-point VTK writer (src_fix/lib/writers/contact_points_vtk.*): the file read back.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "writers/contact_points_vtk.h"

using namespace ohmdem;

TEST(ContactPointsVtk, PointsVerticesAndNamedData)
{
  std::vector<ContactPoint> pts(2);
  pts[0].ball = 7;
  pts[0].race = 0;
  pts[0].at[0] = 0.25;
  pts[0].values = {1.5e-6, -0.5};
  pts[1].ball = 7;
  pts[1].race = 1;
  pts[1].at[1] = -1e-3;
  pts[1].values = {0.125, 3.0};  // exact in binary: 17 digits print it short
  std::ostringstream os;
  write_contact_points_vtk(os, pts, {"h_min", "phase"}, "ohmdem lubricated contacts");
  const std::string expected =
      "# vtk DataFile Version 3.0\nohmdem lubricated contacts\nASCII\nDATASET POLYDATA\n"
      "POINTS 2 double\n0.25 0 0\n0 -0.001 0\n"
      "VERTICES 2 4\n1 0\n1 1\n"
      "POINT_DATA 2\nSCALARS ball double 1\nLOOKUP_TABLE default\n7\n7\n"
      "SCALARS race double 1\nLOOKUP_TABLE default\n0\n1\n"
      "SCALARS h_min double 1\nLOOKUP_TABLE default\n1.5e-06\n0.125\n"
      "SCALARS phase double 1\nLOOKUP_TABLE default\n-0.5\n3\n";
  EXPECT_EQ(os.str(), expected);
}

TEST(ContactPointsVtk, EmptyAndBadInput)
{
  std::ostringstream os;
  write_contact_points_vtk(os, {}, {"C"}, "t");
  EXPECT_NE(os.str().find("POINTS 0 double\nVERTICES 0 0\nPOINT_DATA 0\n"), std::string::npos);
  std::vector<ContactPoint> pts(1);
  pts[0].values = {1.0};
  EXPECT_THROW(write_contact_points_vtk(os, pts, {"a", "b"}, "t"), std::invalid_argument);
  EXPECT_THROW(write_contact_points_vtk(os, pts, {"a b"}, "t"), std::invalid_argument);
}
