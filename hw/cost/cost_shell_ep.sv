// Measurement shell, not part of GIRTD: wraps one adder EP so an FPGA flow
// can place it with two pins. Inputs come from a shift register, outputs fold
// into one register, so every timing path of the EP is register to register.
module cost_shell_ep #(
    parameter int W = 20
) (
    input  logic clk_i,
    input  logic serial_i,
    output logic serial_o
);
  logic [3 * W + 2:0] sr_q;
  logic signed [W-1:0] value, dx;
  always_ff @(posedge clk_i) sr_q <= {sr_q[3*W+1:0], serial_i};
  dda_ep #(.W(W)) u_ep (.clk_i, .op_i(sr_q[2:0]), .value_i(sr_q[W+2:3]), .dx_i(sr_q[2*W+2:W+3]),
                        .dy_i(sr_q[3*W+2:2*W+3]), .value_o(value), .dx_o(dx));
  always_ff @(posedge clk_i) serial_o <= ^{value, dx};
endmodule
