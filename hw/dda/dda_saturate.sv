// EP output stage (fig. 4.20): the integer part of a W-bit register with
// FRAC fraction bits, saturated to 0 .. 2^OUT - 1 when guard bits exist
// above the output, else its low OUT bits.
module dda_saturate #(
    parameter int W = girtd_pkg::COLOR_W,
    parameter int FRAC = girtd_pkg::COLOR_FRAC,
    parameter int OUT = girtd_pkg::COLOR_OUT
) (
    /* verilator lint_off UNUSEDSIGNAL */  // the fraction bits are truncated away
    input  logic signed [W-1:0] value_i,
    /* verilator lint_on UNUSEDSIGNAL */
    output logic [OUT-1:0]      out_o,
    output logic                clipped_o  // the output is not the integer part (for the numerics count)
);
  localparam int INT_W = W - FRAC;
  logic signed [INT_W-1:0] integer_part;
  assign integer_part = value_i[W-1:FRAC];

  if (INT_W > OUT) begin : g_saturate
    always_comb begin
      if (integer_part < 0) out_o = '0;
      else if (integer_part > INT_W'((1 << OUT) - 1)) out_o = '1;
      else out_o = integer_part[OUT-1:0];
    end
    assign clipped_o = integer_part < 0 || integer_part > INT_W'((1 << OUT) - 1);
  end else begin : g_truncate
    assign out_o = integer_part[OUT-1:0];
    assign clipped_o = integer_part < 0;  // a negative integer part read as unsigned
  end
endmodule
