using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;

namespace OperatorPanel.StlGen.V3;

/// <summary>A check that refuses the request: its condition, then STATUS and the error reply (label 2: P = 0, the reply next scan).</summary>
internal static class Refusal
{
    public static StlNetwork If(Layout l, string title, string comment, ReplyStatus status, params (string Mnemonic, string[] Operands)[] condition)
    {
        var net = new NetworkBuilder(title, comment);
        foreach (var (mnemonic, operands) in condition)
        {
            net.Op(mnemonic, operands);
        }

        return net.Op("MOVB", Context.Hex(status), l.B(l.Status)).Op("JMP", Context.Dec(Labels.ErrorReply)).Build();
    }
}
