(** POV-Ray's TRANSFORM (docs/povray-rules.md §14.1): a 4×4 double matrix [M] and its inverse [I], for row
    vectors ([p' = p·M], translation in row 3). Every operation repeats the floating-point operation
    order of POV-Ray's [math/matrices.cpp], so that results agree to the last bit.

    Field [mRC] is row R, column C of [M]; [iRC] the same of [I]. Column 3 is (0,0,0,1) except for
    rounding after an inversion, and it still takes part in compositions, as in POV-Ray. *)

type t = private {
  m00 : float; m01 : float; m02 : float; m03 : float;
  m10 : float; m11 : float; m12 : float; m13 : float;
  m20 : float; m21 : float; m22 : float; m23 : float;
  m30 : float; m31 : float; m32 : float; m33 : float;
  i00 : float; i01 : float; i02 : float; i03 : float;
  i10 : float; i11 : float; i12 : float; i13 : float;
  i20 : float; i21 : float; i22 : float; i23 : float;
  i30 : float; i31 : float; i32 : float; i33 : float;
}

val identity : t
(** [identity] is the transform that changes nothing. *)

val translate : Vec.t -> t
(** [translate v] moves by [v] (§14.2, [Compute_Translation_Transform]). *)

val rotate : Vec.t -> t
(** [rotate a] rotates by [a.x] degrees about x, then [a.y] about y, then [a.z] about z,
    left-handed; the inverse is built from exact transposes (§14.2, [Compute_Rotation_Transform]). *)

val axis_rotate : Vec.t -> float -> t
(** [axis_rotate axis deg] rotates by [deg] degrees about [axis] (left-handed, as [vaxis_rotate]:
    [x] about [y] by 90 gives [<0,0,-1>]); the inverse is the transpose. *)

val scale : Vec.t -> t
(** [scale s] scales by [s] per axis; its inverse divides. Zero components must already have been
    replaced by 1 (§14.2, [Compute_Scaling_Transform]). *)

val matrix : float array -> (t * string list, string) result
(** [matrix a] is [matrix <a0, …, a11>] (§14.1): the 12 numbers fill rows 0–3, columns 0–2. A
    column whose three entries are all below 1e-10 in magnitude gets a 1 on the diagonal, with the
    warning POV-Ray prints (one per such column). A zero determinant is POV-Ray's fatal
    "Singular matrix" error. [Invalid_argument] if [a] does not hold 12 numbers. *)

val invert : float array -> float array option
(** [invert m] is POV-Ray's MInvers of the 4×4 matrix [m] (16 entries, row by row): cofactor
    expansion in its term order; None when the determinant is 0 ("Singular matrix in MInvers"). *)

val of_inverse : float array -> t option
(** [of_inverse i] is the transform whose inverse matrix is [i] (16 entries, row by row) and whose
    matrix is [i] inverted by cofactor expansion ([MInvers]); None when [i] is singular. POV-Ray
    sets up a polygon's frame this way (§15.7). *)

val product : float array -> float array -> float array
(** [product a b] is the 4×4 product [a·b] of two matrices given row by row (16 entries), each
    entry summed over k = 0..3 from left to right, as [MTimesA], [MTimesB] and [MTimesC] do. *)

val inverse_matrix : t -> float array
(** [inverse_matrix t] is [I], row by row (16 entries). *)

val compose : t -> t -> t
(** [compose a b] is "first [a], then [b]": [M = a.M·b.M], [I = b.I·a.I]
    ([Compose_Transforms]). *)

val inverse : t -> t
(** [inverse t] is what [inverse] does inside a [transform {…}] block (§14.3): both matrices are
    inverted by cofactor expansion ([MInvers]), which is not bit-identical to swapping them. In the
    (numerically) singular case where that fails, the two matrices are swapped instead. *)

val point : t -> Vec.t -> Vec.t
(** [point t p] is p·M ([MTransPoint]). *)

val direction : t -> Vec.t -> Vec.t
(** [direction t d] is d·M without the translation ([MTransDirection]). *)

val inv_point : t -> Vec.t -> Vec.t
(** [inv_point t p] is p·I ([MInvTransPoint]). *)

val inv_direction : t -> Vec.t -> Vec.t
(** [inv_direction t d] is d·I without the translation ([MInvTransDirection]). *)

val normal : t -> Vec.t -> Vec.t
(** [normal t n] is n·Iᵀ, the inverse transpose without translation, not normalised
    ([MTransNormal], §14.6). *)

val is_identity : t -> bool
(** [is_identity t] tells whether both matrices are exactly the identity. *)

val normalize : Vec.t -> Vec.t
(** [normalize v] is POV-Ray's [VNormalize]: [v] times the reciprocal of its length (which can
    differ in the last bit from dividing by the length). *)

val bounds : t -> float array -> float array
(** [bounds t box] is the box (min x, y, z, max x, y, z) around the eight corners of [box] mapped
    by [point t] ([Recompute_BBox], §15.8). *)

val to_string : t -> string
(** [to_string t] prints [M] row by row, for tests and debugging. *)

val axis_rotate_rad : Vec.t -> float -> t
(** [axis_rotate_rad axis a] rotates by [a] radians about [axis] ([Compute_Axis_Rotation_Transform]:
    the axis normalised by [normalize], the inverse the transpose). *)

val coordinate : Vec.t -> Vec.t -> float -> float -> t * Vec.t
(** [coordinate origin up radius length] is POV-Ray's [Compute_Coordinate_Transform] (§15.2): the
    canonical space (unit radius, unit length along +z) scaled by [<radius, radius, length>],
    turned so that +z becomes the unit vector [up], and moved to [origin]; with [up] as POV-Ray
    leaves it (its z snapped to ±1 when within 1e-10 of it). *)
