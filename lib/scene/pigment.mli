(** Pigment evaluation: patterns, the value wrap and waves, and colour-map lookup; the default maps,
    and a pigment's transform (POVRAY-3.7 §17). *)

val checker : Vec.t -> float
(** [checker q] is 0 or 1: the parity of [floor(c + 1e-10)] summed over the three coordinates (§17.4). *)

val gradient : Vec.t -> Vec.t -> float
(** [gradient v q] is [q·v], reduced by [fmod 1] only when above 1 (§17.5); [v] is unit length. *)

val hexagon : Vec.t -> float
(** [hexagon q] is 0, 1 or 2: the hexagonal cell of [q] in the XZ plane (§17.6). *)

val brick : Vec.t -> float -> Vec.t -> float
(** [brick size mortar q] is 0 in the mortar and 1 in a brick (§17.7); [mortar] is the stored width. *)

val pattern_value : Scene.pattern -> Vec.t -> float
(** [pattern_value p q] is the raw value of pattern [p] at the pattern-space point [q]. *)

val shape_value : frequency:float -> phase:float -> Scene.wave -> float -> float
(** [shape_value ~frequency ~phase w v] wraps [v] by [fmod(v·frequency + phase, 1.00001)] when
    [frequency] is non-zero, brings a negative result into [0, 1), and applies the wave (§17.1). *)

val lookup : Scene.map_entry array -> float -> Colour.t
(** [lookup map v] is the colour of [map] at [v], by POV-Ray's search of unsorted entries and linear
    blend of all five channels in single precision (§17.2). [map] is not empty. *)

val eval : Scene.patterned -> Vec.t -> Colour.t
(** [eval p x] is the colour of the pattern pigment [p] at the world point [x]: [x] through the
    inverse of the pigment's transform, the pattern, the wrap and wave, the map (§17.1). *)

val colour_at : Scene.pigment -> Vec.t -> Colour.t
(** [colour_at p x] is the colour of any pigment at the world point [x]. *)

val opaque : Scene.pigment -> bool
(** [opaque p] holds when no colour of [p] has a filter or transmit above 1e-10 in magnitude (§17.8). *)

val f32_entry : float -> Colour.t -> Scene.map_entry
(** [f32_entry v c] is a map entry with the value and colour rounded to single precision, as POV-Ray
    stores them (§17.2). *)

val default_map : Scene.pattern -> Scene.map_entry array
(** [default_map p] is the map of [p] written without colours: blue/green for checker, blue, green,
    red for hexagon, grey 0.5 and <0.6,0.15,0.15> for brick, black to white for gradient (§17.3–§17.7). *)

val transform : Scene.pigment -> Transform.t -> Scene.pigment
(** [transform p t] is [p] with [t] composed after its transform (§14.7, §17.1); a plain colour
    keeps the same colour and records the transform ([Solid_placed]). *)
