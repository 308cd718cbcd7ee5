(** What a kind of shape is: the answers the stages ask of a shape's kind rather than of the shape
    itself. Each shape's module writes its kind's traits once ([Torus.traits]);
    [Shape_kind.of_shape] (a scene shape) and [Shape.traits] (a compiled shape) are the one
    exhaustive match from a shape to them, so that a new shape is one line there and the stages
    ask its traits instead of listing shapes. *)

(** How a shape reads the [sturm] keyword among its modifiers. *)
type sturm =
  | No_sturm  (** it takes none: [sturm] is not one of its modifiers *)
  | Sturm_flag  (** [sturm] alone turns it on (torus, prism, lathe, sor: Set_Flag) *)
  | Sturm_bool
      (** [sturm] with an optional boolean (poly, ovus: Bool_Flag of Allow_Float(1.0) > 0) *)
  | Sturm_float
      (** [sturm] with an optional float, on when above 0 (blob: Allow_Float(1.0) > 0.0) *)

type t = {
  name : string;
      (** the keyword that writes the shape ("torus"; a cylinder's is "cone", a text object's
          letter's "glyph") *)
  costly : bool;
      (** testing the shape costs more than testing its box: the scene's search tries the box
          first (docs/povray-rules.md §2.1); false for spheres, planes, triangles, meshes and
          unmoved boxes *)
  box_test_free : bool;
      (** POV-Ray's Intersect_BBox of the shape always passes (spheres, ellipsoids, boxes, planes,
          triangles, polys): a clipped_by or bounded_by around it skips its wrapper's box test *)
  inverse_flag : bool;
      (** [inverse] sets POV-Ray's INVERTED_FLAG on it (Invert_Flag, §16.3): as a CSG member its
          Inside is negated, and an enclosing intersection leaves it out of its box. False where the
          shape's own Invert does nothing (polygon, bicubic patch, parametric) or turns the shape
          over instead (a plane's normal, a julia fractal's own flag) *)
  inside_holds_inverse : bool;
      (** its own Inside test already holds an [inverse] (a quadric's negated coefficients, a julia
          fractal's own flag, a morphed CSG): as a CSG member its Inside is taken as it is, not
          negated by the member's flag *)
  patch : bool;
      (** POV-Ray's PATCH_OBJECT: a shape without an inside (triangles, bicubic patches,
          parametrics), which a CSG inherits from its members. A mesh is one too unless it has an
          inside_vector, which its own value tells (Csg_build.patch) *)
  sturm : sturm;  (** how it reads [sturm] *)
  scale_by_matrix : bool;
      (** moving the whole scene ([--scene-scale]) scales it as a matrix rather than by its own
          Scale, which would change it: a smooth triangle's Scale renormalises its vertex normals,
          which changes how they blend (Place.scene) *)
}

val default : t
(** [default] is the traits of most shapes, which a shape's own are written as changes of: costly,
    its box test not free, [inverse] setting the flag, an inside of its own, no [sturm], scaled by
    its own Scale; its [name] is [""]. *)
