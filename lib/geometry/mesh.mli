(** Triangle meshes as POV-Ray stores them (POVRAY-3.7 §2.6), with a BVH over the faces. A mesh is
    immutable and shared by every object that uses it. *)

type t = private {
  vertices : float array;  (** x y z per vertex, in single precision *)
  normals : float array;  (** x y z per normal: the vertex normals, then one per face *)
  tri_f : float array;  (** 4 per face: plane distance, Perp x y z *)
  tri_i : int array;  (** 9 per face: v1 v2 v3, face normal, n1 n2 n3 (−1 when flat), axis·4 + vaxis, texture *)
  faces : int;
  bvh : Bvh.t;
  inside_vector : Vec.t option;
}

(** A face as written. *)
type face = {
  corners : Vec.t * Vec.t * Vec.t;  (** positions the set-up is computed from (the parsed values for
                                        [mesh], the stored single-precision ones for [mesh2]) *)
  vi : int * int * int;  (** vertex indices *)
  ni : (int * int * int) option;  (** vertex-normal indices of a smooth face *)
  tex : int;  (** texture index, −1 for the mesh's own texture *)
}

val build : vertices:float array -> vertex_normals:float array -> faces:face array -> inside_vector:Vec.t option -> t
(** [build ~vertices ~vertex_normals ~faces ~inside_vector] sets up every face (dropping those without
    area, flattening smooth faces whose three normals are equal) and builds the BVH. Vertices and
    normals must already be single-precision values, normals of unit length. *)

val nearest : t -> int array -> Vec.t -> Vec.t -> float -> float array -> int
(** [nearest m stack o d lo hit] is the nearest face hit at depth ≥ [lo] along the unit direction
    [d] (mesh space), or −1; the depth is stored in [hit.(0)]. *)

val any_hit : t -> int array -> Vec.t -> Vec.t -> float -> float -> bool
(** [any_hit m stack o d lo hi] tells whether a face is hit at a depth in [lo, hi). *)

val inside : t -> int array -> Vec.t -> bool
(** [inside m stack p]: an odd number of faces along the inside vector; false without one. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal m k p] is face [k]'s normal at the mesh-space point [p]. *)

val texture : t -> int -> int
(** [texture m k] is face [k]'s texture index, −1 for the mesh's own. *)

val bounds : t -> float array
(** [bounds m] is the mesh's box: min x, y, z, max x, y, z. *)
