(** The bicubic patch (POV-Ray's shape/bezier.cpp): a Bezier patch of 16 control points in world
    space, cut into flat enough subpatches, each crossed as two triangles whose normal is
    interpolated from the patch's own normals at their corners. Type 0 subdivides for every ray,
    type 1 keeps the subdivision as a tree of bounding spheres. Flat: no inside. *)

(** A node of the type 1 tree: a leaf holds a flat subpatch's corners P00, P03, P33, P30 and its
    parameter range (single precision, as POV-Ray's uvbnds); every node its bounding sphere
    (centre, squared radius). *)
type node =
  | Leaf of { lc : Vec.t; lr2 : float; corners : Vec.t array; u0 : float; u1 : float; v0 : float; v1 : float }
  | Interior of { ic : Vec.t; ir2 : float; children : node array }

type t = {
  patch_type : int;  (** 0 or 1 *)
  u_steps : int;
  v_steps : int;  (** the most splits in u and in v *)
  flatness : float;  (** a subpatch is flat when its control points are nearer than this to its plane *)
  cp : Vec.t array;  (** P[i][j] at 4i + j, i with u, j with v *)
  st : float array;  (** the four uv_vectors (u0, v0, …, u3, v3): the texture coordinates of the corners *)
  tree : node option;
      (** type 1's tree (bezier_tree_builder); None for type 0, and for type 1 when the tree could
          have more than 2^16 leaves (u_steps + v_steps > 16): that patch is subdivided for every
          ray instead, which crosses the same subpatches *)
}

val make : patch_type:int -> u_steps:int -> v_steps:int -> flatness:float -> st:float array -> Vec.t array -> t
(** [make ~patch_type ~u_steps ~v_steps ~flatness ~st cp] is the patch of the 16 points [cp] with
    the uv_vectors [st], its tree built for type 1 (Precompute_Patch_Values) unless it could be
    too big. *)

val texture_uv : t -> float -> float -> float * float
(** [texture_uv b u v] is Compute_Texture_UV: the patch parameters [(u, v)] of a crossing mapped
    into the quadrilateral of the uv_vectors: [(v, u)] with the default ones. *)

val patch_normal : t -> float -> float -> Vec.t
(** [patch_normal b u v] is bezier_value's normal at (u, v): the unit cross product of the
    tangents, or (1, 0, 0) where they are (nearly) parallel. *)

val flatness_of : Vec.t array -> float
(** [flatness_of p] is determine_subpatch_flatness of the 16 points [p]: the largest distance of
    a point from the plane of three distinct corners, or −1 when there are none. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w b o d lo] is the nearest crossing at least [lo] along the ray from [o] along the unit
    [d] (of equal depths the last pushed), or infinity; its report left in [w.crossing]: the
    point, the normal interpolated over the subpatch's triangle, and the texture coordinates
    (BicubicPatch's Iuv, {!texture_uv}); counted ("Bicubic Patch"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w b id o d lo n] pushes every crossing at least [lo] as a hit of the member [id], in
    POV-Ray's order, each with its report (as [depth]'s); it is the new count. *)

val bounds : t -> float array
(** [bounds b] is the control points' box, lower then upper corner. *)

val pov_box : t -> float array
(** [pov_box b] is BicubicPatch::Compute_BBox: Make_BBox_from_min_max of the control points. *)

val traits : Traits.t
(** [traits] is its kind's traits: flat, without an inside, and [inverse] does nothing
    (BicubicPatch::Invert). *)
