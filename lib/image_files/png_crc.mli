(** The CRC-32 every PNG chunk ends with (ISO/IEC 15948 annex D). *)

val crc : string -> int
(** [crc s] is the CRC-32 PNG computes over a chunk's type and data ([s]), in 0 … 2³² − 1. *)
