// The numerics counters of the wrap detector (not part of the thesis'
// design): per EP the uses of a wrapped value, per output the clips, and the
// triangles with a wrap in use or a value the preparer clamped, with the
// first of them. Bit-exact with models/dda (ep_numerics.hpp).
module dda_limits (
    input  logic       clk_i,
    input  logic       rst_ni,
    input  logic       load_i,      // a parameter set is taken this clock
    input  logic       clamped_i,   // ... and the preparer had clamped one of its values
    input  logic       end_i,       // the triangle's last clock
    input  logic [7:0] wrap_use_i,  // R, G, B, T, Z, D1, D2, D3 read wrapped this clock
    input  logic [4:0] clip_i,      // R, G, B, T, Z output clipped on an emitted pixel
    output logic [8*girtd_pkg::COUNT_W-1:0] wraps_o,
    output logic [5*girtd_pkg::COUNT_W-1:0] clips_o,
    output logic [girtd_pkg::COUNT_W-1:0]   triangles_affected_o,
    output logic [girtd_pkg::COUNT_W-1:0]   first_affected_o
);
  localparam int CW = girtd_pkg::COUNT_W;
  logic [CW-1:0] taken_q;  // parameter sets taken so far
  logic affected_q;        // this triangle so far
  logic affected_now;
  assign affected_now = affected_q || |wrap_use_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wraps_o <= '0;
      clips_o <= '0;
      triangles_affected_o <= '0;
      first_affected_o <= '0;
      taken_q <= '0;
      affected_q <= 1'b0;
    end else begin
      for (int i = 0; i < 8; i++) if (wrap_use_i[i]) wraps_o[i*CW+:CW] <= wraps_o[i*CW+:CW] + 1'b1;
      for (int i = 0; i < 5; i++) if (clip_i[i]) clips_o[i*CW+:CW] <= clips_o[i*CW+:CW] + 1'b1;
      if (load_i) begin
        taken_q <= taken_q + 1'b1;
        affected_q <= clamped_i;
      end else begin
        affected_q <= affected_now;
      end
      if (end_i && affected_now) begin
        triangles_affected_o <= triangles_affected_o + 1'b1;
        if (first_affected_o == '0) first_affected_o <= taken_q;
      end
    end
  end
endmodule
