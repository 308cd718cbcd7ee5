(** The complex functions of a hypercomplex julia fractal and the hypercomplex arithmetic around
    them (POV-Ray's math/hcmplx.cpp), in POV-Ray's operation order. *)

(** The functions [julia_fractal] names besides [sqr], [cube] and [reciprocal]. *)
type func = Exp | Ln | Sin | Asin | Cos | Acos | Tan | Atan | Sinh | Asinh | Cosh | Acosh | Tanh | Atanh | Pwr

val apply : func -> ex:float -> ey:float -> float -> float -> float * float
(** [apply f ~ex ~ey x y] is [f (x + iy)] as Complex_Exp … Complex_Pwr compute it, [(ex, ey)]
    being the exponent of [pwr]; 0 where POV-Ray leaves the result unwritten (a zero divisor). *)

val hmult : float -> float -> float -> float -> float -> float -> float -> float -> float * float * float * float
(** [hmult x1 y1 z1 w1 x2 y2 z2 w2] is the hypercomplex product (HMult). *)

val hsqr : float -> float -> float -> float -> float * float * float * float
(** [hsqr x y z w] is the hypercomplex square (HSqr). *)

val hreciprocal : float -> float -> float -> float -> (float * float * float * float) option
(** [hreciprocal x y z w] is the hypercomplex reciprocal (HReciprocal), None where its
    determinant is 0. *)

val hfunc : func -> ex:float -> ey:float -> float -> float -> float -> float -> float * float * float * float
(** [hfunc f ~ex ~ey x y z w] is [f] of the hypercomplex (x, y, z, w) by its duplex form: [f] of
    (x − w) + i(y + z) and of (x + w) + i(y − z), recombined (HFunc). *)
