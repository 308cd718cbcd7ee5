(** The shadow feeler (docs/povray-rules.md §4): the ray from a lit point towards a light, and what the
    objects it crosses leave of the light's colour. *)

val feeler : Context.t -> Hit.t -> slot:int -> Light.sample -> Rgb.t -> Rgb.t
(** [feeler ctx h ~slot smp lc] is the colour [lc] of the light sample [smp] after the shadow ray
    from the hit [h] (from {!Hit.origin}, inside the interiors of the ray that met it) along the sample's
    direction towards the light at its distance; [slot] is the light's shadow-cache slot.
    POV-Ray (TracePointLightShadowRay): the opaque object that last blocked this light (in this
    worker, at this kind of level) is tested first, for a hit from MIN_ISECT_DEPTH (1e-4) to the
    light itself; a hit there is a full shadow. Otherwise the nearest blocker is searched for, hits
    counting from 1e-3 to the light minus 1e-3: an opaque one is a full shadow and becomes the
    cached object; a transparent one filters the light by its colour where the ray crosses it
    (and its fade, inside it), and the ray goes on from there. The robust mode counts every hit
    from the lifted origin to the light minus a relative margin, the cached object's too. *)
