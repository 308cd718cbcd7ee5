(** Local illumination (docs/povray-rules.md §3.3, §18.2, §18.3): what the light sources add to a
    surface point — diffuse (N·L, brilliance), Phong and specular highlights (metallic tint) —
    from each sample of light they give it ({!Light.sample}), each through its shadow feeler. *)

val local : Context.t -> Hit.t -> Compiled.surface -> Vec.t -> Rgb.t
(** [local ctx h s n] is the local illumination of the surface [s] at the hit [h] with the layer
    normal [n] (turned toward the ray): its ambient and emitted colour plus, when [s] is lit, the
    diffuse, phong and specular terms of every sample of every light, each sample through its
    shadow feeler, summed in single precision the way POV-Ray sums them: per light first, then
    into the colour. An object with double_illuminate is lit from behind too (§16.6). With the
    hit's light colour cache on ({!Hit.memo}), a light's shadow feeler is sent only the first time
    the light is tested at this hit (the layers and entries of one texture share it). *)

val iridescence : Compiled.t -> Compiled.surface -> Vec.t -> Vec.t -> Vec.t -> Vec.t -> Rgb.t -> Rgb.t
(** [iridescence sc s l d n p c] is [c] tinted by the thin film of [s] (POV-Ray's
    ComputeIridColour): light arriving along [l], seen along [d], at the point [p] with the normal
    [n]; the phase 2π·thickness·(|n·l| + |n·d|) over each of the scene's irid wavelengths, the
    thickness varied by 5 octaves of turbulence when [s] has an irid turbulence. *)

val metallic_factor : float -> float -> Rgb.t -> Rgb.t -> Rgb.t
(** [metallic_factor metallic cos_angle c lc] is [lc] tinted by the surface colour [c] with
    POV-Ray's empirical metallic Fresnel term (§3.3), for highlights and metallic reflection. *)
