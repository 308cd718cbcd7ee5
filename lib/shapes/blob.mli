(** The blob (POV-Ray's shape/blob.cpp, its bounding sphere tree from bounding/bsphere.cpp): the
    surface where the sum of its components' fields equals the threshold. A component of radius
    r and strength s adds s·(1 − d²/r²)² where d < r (d: the distance to a sphere's centre or a
    cylinder's axis). A cylinder component is three elements: the cylinder and the hemispheres
    closing its ends. Components are kept and summed in POV-Ray's order: the last written first,
    then as its bounding sphere hierarchy visits them. *)

(** What an element is: a sphere (in blob space, no transform), an ellipsoid (a sphere with a
    transform of its own), a cylinder along z from 0 to [len] in its own space, and that
    cylinder's base (z ≤ 0) and apex (z ≥ [len]) hemispheres. *)
type kind = Sphere | Ellipsoid | Base_hemisphere | Apex_hemisphere | Cylinder

(** A component as parsed and moved (Blob_Element before Make_Blob). *)
type component = {
  kind : kind;  (** [Sphere], [Ellipsoid] or [Cylinder] *)
  origin : Vec.t;  (** a sphere's or ellipsoid's centre (in the ellipsoid's own space) *)
  len : float;  (** a cylinder's length *)
  rad2 : float;  (** the radius squared *)
  strength : float;
  ctrans : Transform.t option;  (** its own space to blob space; None for a sphere *)
  tex : int;  (** its own texture, an index into the scene's list of the blob's textures; −1: none *)
}

(** A blob as the interpreter builds it. *)
type t = {
  components : component list;  (** the last written first *)
  threshold : float;
  sturm : bool;
  hierarchy : bool;  (** POV-Ray's bounding sphere tree over the elements (on unless [hierarchy off]) *)
  trans : Transform.t option;  (** blob space to world: every object modifier composed *)
  box : float array option;
      (** POV-Ray's box ({!Pov_box}) once the blob is set up (Make_Blob's Compute_BBox), mapped by
          every later transform; None while its own block is read *)
}

val sphere_component : centre:Vec.t -> radius:float -> strength:float -> component
(** [sphere_component ~centre ~radius ~strength] is [sphere { centre, radius, strength }]. *)

val cylinder_component : base:Vec.t -> apex:Vec.t -> radius:float -> strength:float -> component option
(** [cylinder_component ~base ~apex ~radius ~strength] is [cylinder { base, apex, radius, strength }]
    in its frame (Compute_Coordinate_Transform of the base and the unit axis); None when the ends
    are closer than 1e-10 (POV-Ray's "Degenerate cylindrical component"). *)

val translate_component : component -> Vec.t -> component
(** [translate_component c v] is Translate_Blob_Element: a sphere's centre moves, any other
    component composes the translation into its transform. *)

val rotate_component : component -> Vec.t -> component
(** [rotate_component c v] is Rotate_Blob_Element: a sphere's centre is rotated (MTransPoint). *)

val scale_component : component -> Vec.t -> component
(** [scale_component c v] is Scale_Blob_Element: a uniform scale of a sphere scales its centre
    and radius by [v.x]; a non-uniform one makes it an ellipsoid with the scale as its transform. *)

val transform_component : component -> Transform.t -> component
(** [transform_component c tr] is Transform_Blob_Element: composed into the component's
    transform, a sphere becoming an ellipsoid. *)

val with_texture : component -> int -> component
(** [with_texture c i] is [c] with its own texture, the scene's [i]th texture of the blob. *)

val compute_box : t -> float array
(** [compute_box b] is Compute_BBox: the box of the bounding spheres of the elements of positive
    strength, in single precision, mapped by the blob's transform (Recompute_BBox). *)

val finish : t -> t
(** [finish b] is [b] set up after its block (Make_Blob): its box computed. *)

val transform : t -> Transform.t -> t
(** [transform b tr] is Blob::Transform: composed into the blob's transform, its box, once set
    up, mapped. *)

(** One element as Make_Blob sets it up: field coefficients c0 = s/r⁴, c1 = −2s/r², c2 = s. *)
type element = {
  ekind : kind;
  index : int;  (** its place in the blob's element list *)
  ox : float;
  oy : float;
  oz : float;
  elen : float;
  erad2 : float;
  c0 : float;
  c1 : float;
  c2 : float;
  etr : Transform.t;  (** its own space to blob space; the identity for a sphere, which has none *)
  etex : int;  (** its component's texture, −1: none *)
}

(** A blob ready to trace. *)
type compiled = {
  elems : element array;
  thresh : float;
  csturm : bool;
  ctr : Transform.t option;
  tree : Blob_tree.t;  (** the bounding sphere hierarchy (none with [hierarchy off]) *)
  cbox : float array;  (** POV-Ray's box *)
  exact : float array;  (** the blob-space box in doubles, mapped: lower and upper corner *)
  textured : bool;  (** some component has a texture of its own (MULTITEXTURE_FLAG) *)
}

val compile : t -> compiled
(** [compile b] is [b]'s elements (each cylinder followed by its base and apex hemispheres) and,
    with [hierarchy], {!Blob_tree.build} over their bounding spheres (get_element_bounding_sphere:
    a transformed element's radius is the largest side of the single-precision box of the cube
    [0, r]³ mapped by its transform, squared, plus 1e-10). *)

val node_count : compiled -> int
(** [node_count c] is the number of nodes of [c]'s hierarchy (0 without one). *)

val depth_tolerance : float
(** 1e-2: DEPTH_TOLERANCE of blob.cpp, the least depth of a hit (in world units along the ray). *)

val field : compiled -> Vec.t -> float
(** [field c p] is calculate_field_value at the world point [p]: the sum of the elements' fields,
    visited in the hierarchy's order (a sphere's counts where d² < r², the others' where d² ≤ r²). *)

val inside : compiled -> Vec.t -> bool
(** [inside c p] is Blob::Inside before its inversion: [field c p] > threshold − 1e-6. *)

val normal : compiled -> Vec.t -> Vec.t
(** [normal c p] is Blob::Normal at the world point [p]: the sum of the elements' gradient terms
    −(2·c0·d² + c1)·V (V mapped by the element's MTransNormal), made unit ((1, 0, 0) where it is
    0), then mapped by the blob's transform and normalised. *)

val weights : compiled -> Vec.t -> (float * int) list
(** [weights c p] is Determine_Textures at the world point [p]: each element whose field is not
    0 there, in the hierarchy's order, with |field| as its weight (single precision), the
    weights scaled to sum to 1; paired with the element's texture index (−1: the blob's own). *)

val bounds : compiled -> float array
(** [bounds c] is the blob's box in doubles (lower corner, upper corner). *)

val pov_box : compiled -> float array
(** [pov_box c] is POV-Ray's box of the blob. *)

val traits : Traits.t
(** [traits] is its kind's traits: [sturm] takes an optional float. *)

val describe : (float -> string) -> (Vec.t -> string) -> (Transform.t -> string) -> t -> string
(** [describe num vec matrix b] is the [--dump] text of [b] (without its own transform), numbers
    written by [num], vectors by [vec] and the components' transforms by [matrix]. *)
