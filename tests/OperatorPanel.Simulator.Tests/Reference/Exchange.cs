using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>Sends one raw request body to a <see cref="ReferencePlc"/> and decodes its reply.</summary>
internal static class Exchange
{
    /// <summary>
    /// "ST SQ CM" and payload as hex; null when the station stays silent. The reply's REQCHECK must be the request's
    /// check; the returned frame's payload is STATUS and the data, REQCHECK taken out.
    /// </summary>
    public static FreeportFrame? Send(ReferencePlc plc, string head, string payload = "")
    {
        var h = Hex(head);
        var request = new FreeportFrame(h[0], h[1], h[2], Hex(payload));
        var reply = plc.HandleFrame(FrameCodec.Encode(request));
        if (reply is null)
        {
            return null;
        }

        FrameCodec.TryDecode(reply, out var frame, out var error).Should().BeTrue($"the reply must be a valid frame ({error})");
        frame.Payload.Length.Should().BeGreaterThanOrEqualTo(3, "every reply carries STATUS and REQCHECK");
        ((frame.Payload[1] << 8) | frame.Payload[2]).Should().Be(FrameCodec.CheckOf(request), "REQCHECK is the check of the request answered");
        return frame with { Payload = [frame.Payload[0], .. frame.Payload.AsSpan()[3..]] };
    }

    public static ImmutableArray<byte> Hex(string text) =>
        [.. Convert.FromHexString(text.Replace(" ", string.Empty, StringComparison.Ordinal))];
}
