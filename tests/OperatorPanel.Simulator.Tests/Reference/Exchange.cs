using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>Sends one raw request body to a <see cref="ReferencePlc"/> and decodes its reply.</summary>
internal static class Exchange
{
    /// <summary>"ST SQ CM" and payload as hex; null when the station stays silent.</summary>
    public static FreeportFrame? Send(ReferencePlc plc, string head, string payload = "")
    {
        var h = Hex(head);
        var reply = plc.HandleFrame(FrameCodec.Encode(new FreeportFrame(h[0], h[1], h[2], Hex(payload))));
        if (reply is null)
        {
            return null;
        }

        FrameCodec.TryDecode(reply, out var frame, out var error).Should().BeTrue($"the reply must be a valid frame ({error})");
        return frame;
    }

    public static ImmutableArray<byte> Hex(string text) =>
        [.. Convert.FromHexString(text.Replace(" ", string.Empty, StringComparison.Ordinal))];
}
