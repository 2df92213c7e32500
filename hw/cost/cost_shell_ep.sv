// Measurement shell, not part of GIRTD: wraps one adder EP so an FPGA flow
// can place it with two pins. Inputs come from a shift register, outputs fold
// into one register, so every timing path of the EP is register to register.
module cost_shell_ep #(
    parameter int W = girtd_pkg::COLOR_W
) (
    input  logic clk_i,
    input  logic serial_i,
    output logic serial_o
);
  localparam int O = girtd_pkg::OP_W;
  logic [3 * W + O:0] sr_q;  // op, value, dx, dy, load
  logic signed [W-1:0] value, dx;
  always_ff @(posedge clk_i) sr_q <= {sr_q[3*W+O-1:0], serial_i};
  dda_ep #(.W(W)) u_ep (.clk_i, .load_i(sr_q[3*W+O]), .op_i(sr_q[O-1:0]), .value_i(sr_q[O+:W]), .dx_i(sr_q[O+W+:W]),
                        .dy_i(sr_q[O+2*W+:W]), .value_o(value), .dx_o(dx), .wrapped_o());
  always_ff @(posedge clk_i) serial_o <= ^{value, dx};
endmodule
