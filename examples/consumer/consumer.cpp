// SPDX-License-Identifier: GPL-3.0-or-later
// Wraps the corners of a box and its centre with the installed pcl_wrap. The paper's W passes
// through the centre, and so does the surface: one of the box's 12 triangles dips to it as 3.
#include <pcl_wrap/wrap.h>

#include <pcl/point_types.h>

#include <iostream>

int
main ()
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (int i = 0; i < 8; ++i)
    cloud->push_back (pcl::PointXYZ (float (i & 1), float ((i >> 1) & 1) * 1.1f, float ((i >> 2) & 1) * 1.3f));
  cloud->push_back (pcl::PointXYZ (0.5f, 0.55f, 0.65f)); // the centre

  pcl_wrap::Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  std::cout << mesh.polygons.size () << " triangles\n";
  return mesh.polygons.size () == 14 ? 0 : 1;
}
