// The X or Y element processor: an up/down counter with its AUX register
// (fig. 4.22). The limit compares live in the sequencer.
module dda_counter #(
    parameter int W = girtd_pkg::XY_W,
    parameter logic [girtd_pkg::OP_W-1:0] INC_OP = girtd_pkg::OP_XINC,
    parameter bit CAN_DEC = 1'b1,  // Y only counts up (§4.2.2: never Y--)
    parameter logic [girtd_pkg::OP_W-1:0] DEC_OP = girtd_pkg::OP_XDEC
) (
    input  logic         clk_i,
    input  logic         load_i,  // a parameter set is taken: value_i (apart from op_i, as in dda_ep)
    input  logic [girtd_pkg::OP_W-1:0] op_i,
    input  logic [W-1:0] value_i,
    output logic [W-1:0] value_o
);
  logic [W-1:0] value_q, value_d, aux_q;

  always_comb begin
    value_d = value_q;
    if (op_i == INC_OP) value_d = value_q + 1'b1;
    else if (CAN_DEC && op_i == DEC_OP) value_d = value_q - 1'b1;
    else if (op_i == girtd_pkg::OP_RESTORE) value_d = aux_q;
  end

  always_ff @(posedge clk_i) begin
    value_q <= load_i ? value_i : value_d;
    if (op_i == girtd_pkg::OP_SAVE) aux_q <= value_q;
  end

  assign value_o = value_q;
endmodule
