(* The one match from a scene shape to its kind's traits. *)

let csg = { Traits.default with name = "csg"; costly = false; inside_holds_inverse = true }

let of_shape : Scene.shape -> Traits.t = function
  | Sphere { trans = None; _ } -> Sphere.traits
  | Sphere { trans = Some _; _ } -> Sphere.ellipsoid_traits
  | Plane _ -> Plane.traits
  | Triangle _ -> Triangle.traits
  | Smooth_triangle _ -> Triangle.smooth_traits
  | Mesh _ -> Mesh.traits
  | Box { trans = None; _ } -> Box.traits
  | Box { trans = Some _; _ } -> Box.moved_traits
  | Cone _ -> Cone.traits
  | Disc _ -> Disc.traits
  | Torus _ -> Torus.traits
  | Polygon _ -> Polygon.traits
  | Poly _ -> Poly.traits
  | Quadric _ -> Quadric.traits
  | Blob _ -> Blob.traits
  | Height_field _ -> Hfield.traits
  | Superellipsoid _ -> Superellipsoid.traits
  | Ovus _ -> Ovus.traits
  | Sphere_sweep _ -> Sphere_sweep.traits
  | Prism _ -> Prism.traits
  | Lathe _ -> Lathe.traits
  | Sor _ -> Sor.traits
  | Isosurface _ -> Isosurface.traits
  | Julia _ -> Julia.traits
  | Parametric _ -> Parametric.traits
  | Bicubic _ -> Bezier.traits
  | Csg _ -> csg
  | Glyph _ -> Glyph.traits
