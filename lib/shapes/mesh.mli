(** Triangle meshes as POV-Ray stores them (docs/povray-rules.md §2.6), with a BVH over the faces. A mesh is
    immutable and shared by every object that uses it. *)

type f32s = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t
type i32s = (int32, Bigarray.int32_elt, Bigarray.c_layout) Bigarray.Array1.t

type t = private {
  vertices : f32s;  (** x y z per vertex *)
  vnormals : f32s;  (** x y z per vertex normal *)
  fgeom : f32s;  (** 6 per face: face normal x y z, Perp x y z *)
  fdist : float array;  (** 1 per face: the plane distance, computed in double precision and rounded to single *)
  fidx : i32s;  (** 7 per face: v1 v2 v3, n1 n2 n3 (−1 when flat), axis + 4·vaxis + 16·(texture + 1) *)
  faces : int;
  bvh : Bvh.t;
  inside_vector : Vec.t option;
  uvs : float array;  (** u v per UV coordinate, double precision; empty: every corner's is (0, 0) *)
  fuv : i32s;  (** 3 per face: its corners' indices into [uvs], swapped with the vertices; empty: every corner's is the first *)
}

val build :
  vertices:float array ->
  vertex_normals:float array ->
  fv:int array ->
  fn:int array ->
  ftex:int array ->
  corners:float array option ->
  inside_vector:Vec.t option ->
  t
(** [build ~vertices ~vertex_normals ~fv ~fn ~ftex ~corners ~inside_vector] sets up every face and
    builds the BVH. Per face: three vertex indices in [fv], three vertex-normal indices in [fn] (−1
    for a flat face; an empty [fn] makes every face flat), a texture index in [ftex] (−1: the mesh's own; an empty [ftex]: every face uses the mesh's
    own). [corners] (9 floats per face)
    are the positions the set-up is computed from when they differ from the stored vertices (the
    parsed values of a [mesh]). Faces without area are dropped, smooth faces whose three normals are
    equal become flat. Vertices and normals must be single-precision values, normals unit length. *)

val build_uv :
  uvs:float array ->
  fuv:int array ->
  vertices:float array ->
  vertex_normals:float array ->
  fv:int array ->
  fn:int array ->
  ftex:int array ->
  corners:float array option ->
  inside_vector:Vec.t option ->
  t
(** [build_uv ~uvs ~fuv …] is [build …] with UV coordinates: [uvs] holds u v for each (empty:
    every corner at (0, 0)), [fuv] three indices into them per face in the corners' order as
    written (empty: every corner uses the first). A face whose first two corners its set-up swaps
    has its first two UV indices swapped too (Compute_Mesh_Triangle). Nothing is stored for a
    mesh without them. *)

val nearest : t -> float array -> Vec.t -> Vec.t -> float -> float array -> int
(** [nearest m stack o d lo hit] is the nearest face hit at depth ≥ [lo] along the unit direction
    [d] (mesh space), or −1; the depth is stored in [hit.(0)]. *)

val nearest_within : Limits.t -> t -> float array -> Vec.t -> Vec.t -> float -> float array -> int
(** [nearest_within lim m stack o d lo hit] is [nearest] with the faces' depth limits [lim]. *)

val iter_hits : Limits.t -> t -> float array -> Vec.t -> Vec.t -> (int -> float -> unit) -> unit
(** [iter_hits lim m stack o d f] calls [f face depth] for every face the ray crosses within the
    limits [lim], in the order the mesh's hierarchy is walked (for CSG, §16.2). *)

val any_hit : t -> float array -> Vec.t -> Vec.t -> float -> float -> bool
(** [any_hit m stack o d lo hi] tells whether a face is hit at a depth in [lo, hi). *)

val inside : t -> float array -> Vec.t -> bool
(** [inside m stack p]: an odd number of faces along the inside vector; false without one. *)

val inside_along : t -> float array -> Vec.t -> Vec.t -> bool
(** [inside_along m stack p d]: an odd number of faces hit from [p] along the unit direction [d]
    (the inside vector brought into mesh space); false when the mesh has no inside vector. *)

val face_normal : t -> int -> Vec.t
(** [face_normal m k] is face [k]'s flat (geometric) unit normal in mesh space. *)

val raw_normal : t -> int -> Vec.t -> Vec.t
(** [raw_normal m k p] is face [k]'s normal at the mesh-space point [p] before normalisation: the
    interpolated vertex normal of a smooth face, the stored face normal of a flat one. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal m k p] is face [k]'s normal at the mesh-space point [p]. *)

val texture : t -> int -> int
(** [texture m k] is face [k]'s texture index, −1 for the mesh's own. *)

val uv : t -> int -> Vec.t -> Vec.t
(** [uv m k p] is Mesh::UVCoord of face [k] at the mesh-space point [p], (u, v, 0): the corners'
    UV coordinates blended by weights 1 + t1/t2 from the projection of [p] onto each corner's
    height over the opposite side, computed on the single-precision vertices. *)

val extent : t -> float array
(** [extent m] is the exact extent of the faces' corners (min x, y, z, max x, y, z), as POV-Ray
    computes a mesh's bounding box. *)

val bounds : t -> float array
(** [bounds m] is the mesh's box: min x, y, z, max x, y, z. *)

type placed = { mesh : t; tr : Transform.t; moved : bool }
(** A mesh placed in the scene: the shared data, and its transform when it has one ([moved]); an
    unmoved mesh is searched in world space as it is, like POV-Ray's mesh without a Trans (§2.6). *)

val place : t -> Transform.t option -> placed
(** [place m tr] is [m] placed by [tr], or as it is. *)

val depth : Scratch.t -> placed -> Vec.t -> Vec.t -> float -> float
(** [depth w m o d lo] is the nearest face hit at least [lo] (Mesh::Intersect: a moved mesh is
    searched in its own space with the direction renormalised, the depth divided by its length),
    its face left in [w.part]; or infinity. The test and a hit are counted. *)

val hits : Scratch.t -> placed -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w m id o d lo n] pushes every face crossing at least [lo] as hits of the member [id], in
    the order the mesh's hierarchy is walked; it is the new count. *)

val placed_normal : placed -> int -> Vec.t -> Vec.t
(** [placed_normal m face p] is the unit world normal of [face] at [p]: with a transform, the
    unnormalised mesh-space normal by the inverse transpose, normalised once (§2.6, §14.6). *)

val placed_face_normal : placed -> int -> Vec.t
(** [placed_face_normal m face] is the face's flat world normal. *)

val placed_inside : float array -> placed -> Vec.t -> bool
(** [placed_inside stack m p] is Mesh::Inside along the inside vector, both brought into mesh
    space, the direction renormalised; [stack] is traversal room (512 floats). *)

val placed_uv : placed -> int -> Vec.t -> Vec.t
(** [placed_uv m face p] is [uv] of [face] at the world point [p], brought into mesh space when
    the mesh is moved. *)

val placed_bounds : placed -> float array
(** [placed_bounds m] is the mesh's box, its corners mapped when it is moved. *)

val placed_pov_box : placed -> float array
(** [placed_pov_box m] is POV-Ray's box: its single-precision vertices' extent, mapped when moved. *)

val traits : Traits.t
(** [traits] is its kind's traits: tested through its own hierarchy, not after its box (a patch
    unless it has an inside_vector, which its value tells). *)
