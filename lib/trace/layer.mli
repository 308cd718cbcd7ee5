(** One layer of a texture shaded at a hit: the loop body of POV-Ray's ComputeLightedTexture
    (docs/povray-rules.md §3.2, §5.2), shared by a plain texture (one layer) and the layers of any
    other. *)

type t = {
  surface : Compiled.surface;  (** the layer's surface at the point: its pigment evaluated there *)
  normal : Vec.t;  (** the layer's normal: N bent by its normal pattern, made unit *)
  reflectivity : Rgb.t;  (** k_r, the reflection colour at the layer's angle of incidence, metallic tint included *)
  weight : float;  (** the weight of its reflected ray (§5.2, taken before the metallic tint) *)
  local : Rgb.t;  (** its local illumination: ambient, emission and each light through its shadow feeler *)
}

val shade : Context.t -> Hit.t -> warps:Scene.warp list list -> trans:float -> Vec.t -> Compiled.surface -> t
(** [shade ctx h ~warps ~trans q s] is the layer [s] shaded at the hit [h], its pigment and normal
    pattern evaluated at [q] (the hit's point, or where its patterned textures [warps], the
    outermost first, moved it; their spaces bend the normal), seen through the translucency
    [trans] the layers above it leave (1 for the top layer). A normal pattern replaces the hit's
    {!Hit.t.pnormal}. *)
