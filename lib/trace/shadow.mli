(** The shadow feeler (docs/povray-rules.md §4): the ray from a lit point towards a light, and what the
    objects it crosses leave of the light's colour. *)

val feeler : Context.t -> slot:int -> Vec.t -> Vec.t -> float -> Vec.t -> float -> int list -> Rgb.t -> Rgb.t
(** [feeler ctx ~slot p ng e l dist interiors lc] is the light colour [lc] after the shadow ray
    from [p] (on a surface with geometric normal [ng] and error bound [e], for the robust mode)
    along the unit [l] towards the light at [dist]; [slot] is the light's shadow-cache slot.
    POV-Ray (TracePointLightShadowRay): the opaque object that last blocked this light (in this
    worker, at this kind of level) is tested first, for a hit from MIN_ISECT_DEPTH (1e-4) to the
    light itself; a hit there is a full shadow. Otherwise the nearest blocker is searched for, hits
    counting from 1e-3 to the light minus 1e-3: an opaque one is a full shadow and becomes the
    cached object; a transparent one filters the light by its colour where the ray crosses it
    (and its fade, inside it), and the ray goes on from there. The robust mode counts every hit
    from the lifted origin to the light minus a relative margin, the cached object's too. *)
