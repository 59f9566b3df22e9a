using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// Mutations of a valid reply, raw (characters flipped, cut, inserted; '&gt;' lost; '&lt;' inside; lowercase hex;
/// 300 characters of garbage) or re-encoded with a good check (another station, SEQ, REQCHECK, status or length), so the
/// decoder's own checks past the CRC are reached too.
/// </summary>
internal static class ReplyMutator
{
    public const int Kinds = 13;

    public static ReplyMutation Mutate(byte[] reply, PlcRequest request, Random random)
    {
        FrameCodec.TryDecode(reply, out var frame, out _).Should().BeTrue("the mutator starts from a valid reply");
        var chars = (byte[])reply.Clone();
        switch (random.Next(Kinds))
        {
            case 0:
                var at = random.Next(chars.Length);
                var was = chars[at];
                chars[at] = (byte)random.Next(256);
                return new(chars, $"character {at} {was:X2} became {chars[at]:X2}", chars[at] == was);
            case 1:
                var cut = random.Next(1, chars.Length - 1);
                return new([.. chars[..cut], .. chars[(cut + 1)..]], $"character {cut} deleted", false);
            case 2:
                var put = random.Next(1, chars.Length - 1);
                var extra = HexOrCheckCharacter(random);
                return new([.. chars[..put], extra, .. chars[put..]], $"{(char)extra} inserted at {put}", false);
            case 3:
                var length = random.Next(0, chars.Length);
                return new(chars[..length], $"truncated to {length} characters", false);
            case 4:
                return new(chars[..^1], "no '>'", false);
            case 5:
                var start = random.Next(1, chars.Length - 1);
                // Right after the first '<' it only restarts the same frame: a frame reader rightly takes the rest.
                return new([.. chars[..start], (byte)'<', .. chars[start..]], $"'<' inserted at {start}", start == 1);
            case 6:
                var lower = Encoding.ASCII.GetBytes(Encoding.ASCII.GetString(chars).ToLowerInvariant());
                return new(lower, "hex in lowercase", lower.AsSpan().SequenceEqual(chars));
            case 7:
                var station = (byte)((frame.Station + random.Next(1, 255)) % 256);
                return Encoded(frame with { Station = station }, $"from station {station}", false);
            case 8:
                var sequence = (byte)(frame.Sequence + random.Next(1, 256));
                return Encoded(frame with { Sequence = sequence }, $"SEQ {sequence:X2}", false);
            case 9:
                var check = (ushort)(((frame.Payload[1] << 8) | frame.Payload[2]) + random.Next(1, 65536));
                return Encoded(frame with { Payload = frame.Payload.SetItem(1, (byte)(check >> 8)).SetItem(2, (byte)check) }, $"REQCHECK {check:X4}", false);
            case 10:
                var status = (byte)random.Next(8, 256);
                return Encoded(frame with { Payload = frame.Payload.SetItem(0, status) }, $"status {status:X2}", false);
            case 11:
                return LengthChanged(frame, request, random);
            default:
                var garbage = new byte[300];
                for (var i = 0; i < garbage.Length; i++)
                {
                    garbage[i] = random.Next(10) == 0 ? (byte)"<>"[random.Next(2)] : (byte)random.Next(32, 127);
                }

                return new(garbage, "300 characters of garbage", false);
        }
    }

    private static ReplyMutation LengthChanged(FreeportFrame frame, PlcRequest request, Random random)
    {
        var payload = frame.Payload.Length > 3 && random.Next(2) == 0
            ? frame.Payload.RemoveAt(frame.Payload.Length - 1)
            : frame.Payload.Add((byte)random.Next(256));
        if (FrameCodec.OverheadChars + (2 * (FreeportFrame.OverheadBytes + payload.Length)) > ProtocolLimits.MaxFrameChars)
        {
            payload = frame.Payload.RemoveAt(frame.Payload.Length - 1);
        }

        // READ LIST and READ CHANGES replies carry what the stored list holds; a status byte other than OK carries no data.
        var free = frame.Payload[0] == 0 && request is ReadListRequest or ReadChangesRequest;
        return Encoded(frame with { Payload = payload }, $"payload {payload.Length} bytes instead of {frame.Payload.Length}", free);
    }

    private static ReplyMutation Encoded(FreeportFrame frame, string how, bool mayBeAccepted) =>
        new(FrameCodec.Encode(frame with { Payload = [.. frame.Payload] }), how + " (good check)", mayBeAccepted);

    private static byte HexOrCheckCharacter(Random random) =>
        (byte)"0123456789ABCDEF`abcdefghijklmno"[random.Next(32)];
}
