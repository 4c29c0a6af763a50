"""From a numpy mesh to balls, medial mesh and thickness in five lines (medialaxis.arrays)."""
import medialaxis
vertices, triangles = medialaxis.demo_shape("jack")  # numpy: (n, 3) float64, (m, 3) int64
balls = medialaxis.medial_axis(vertices, triangles, samples=5000, seed=1, threads=2)
mesh = medialaxis.medial_mesh(vertices, triangles, balls=balls, threads=2)
wall = medialaxis.thickness(vertices, triangles, below=0.3, threads=2)
print(balls, mesh, wall, sep="\n")
