using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Tests.Hosting;

namespace OperatorPanel.Simulator.Tests.Fuzz;

/// <summary>
/// The generated handler (Handler224Station2.awl) running in the STL interpreter, fed mutated and garbage request
/// frames (seeded): the CPU stays in RUN without a fault, whatever comes back is one valid reply frame from station 2,
/// and after each bad frame the station answers a good IDENTIFY at the latest on its retry: no input wedges the receive.
/// </summary>
public sealed class HandlerRequestFuzzTests
{
    private static readonly Station Station2 = new(2);

    /// <summary>Long enough for the longest reply at 9600 baud (255 characters, about 270 ms) after the handler's scans.</summary>
    private static readonly TimeSpan ReplyWindow = TimeSpan.FromMilliseconds(400);

    [Fact]
    public void Handler_MutatedAndGarbageRequests_KeepsRunningAndAnswersTheNextGoodRequest()
    {
        var random = new Random(8027);
        var line = StlStations.Line(runProcess: false, 2);
        var station = line.Stations[0];
        var failures = new List<string>();
        for (var i = 0; i < 60; i++)
        {
            var (request, how) = Mutated(random);
            var reply = StlStations.Exchange(line, request, ReplyWindow);
            if (reply.Count > 0 && !IsReplyFromStation2(reply.Select(c => c.Value).ToArray()))
            {
                failures.Add($"#{i} {how}: the answer is not one valid reply from station 2");
            }

            // A frame cut before its '>' leaves RCV collecting: the next request ends that message (a '<' inside a
            // message is data to RCV), and the PC's retry after the time-out gets through. So: two attempts.
            var answered = Enumerable.Range(0, 2).Any(attempt =>
                IsReplyFromStation2([.. StlStations.Exchange(line, StlStations.Identify(2, (byte)(i + attempt)), ReplyWindow).Select(c => c.Value)]));
            if (!answered)
            {
                failures.Add($"#{i} {how}: two good IDENTIFY requests after it got no valid reply");
            }

            if (station.Mode != OperatingMode.Run || station.Plc.Fault is { } fault)
            {
                failures.Add($"#{i} {how}: the CPU left RUN ({station.Plc.Fault})");
                break;
            }
        }

        failures.Should().BeEmpty();
    }

    private static bool IsReplyFromStation2(byte[] chars) =>
        FrameCodec.TryDecode(chars, out var frame, out _) && frame.IsReply && frame.Station == Station2.Address;

    private static (byte[] Frame, string How) Mutated(Random random)
    {
        var valid = random.Next(3) switch
        {
            0 => RequestCodec.Encode(new ReadRequest(Station2, 7, [new ReadItem((ProtocolArea)random.Next(1, 6), random.Next(65536), random.Next(1, 40))])),
            1 => RequestCodec.Encode(new WriteBlockRequest(Station2, 7, ProtocolArea.V, random.Next(4000), [.. Enumerable.Range(0, random.Next(1, 20)).Select(_ => (byte)random.Next(256))])),
            _ => RequestCodec.Encode(new WriteBitRequest(Station2, 7, ProtocolArea.M, random.Next(64), random.Next(8), random.Next(2) == 0)),
        };
        var chars = (byte[])valid.Clone();
        switch (random.Next(5))
        {
            case 0:
                var at = random.Next(1, chars.Length - 1);
                chars[at] = (byte)random.Next(256);
                return (chars, $"character {at} of a request became {chars[at]:X2}");
            case 1:
                var length = random.Next(1, chars.Length);
                return (chars[..length], $"request cut to {length}");
            case 2:
                // A good check over a body whose length field or data no longer agree.
                FrameCodec.TryDecode(valid, out var frame, out _);
                var payload = frame.Payload.Length > 1 && random.Next(2) == 0 ? frame.Payload.RemoveAt(frame.Payload.Length - 1) : frame.Payload.Add(0xFF);
                return (FrameCodec.Encode(frame with { Payload = payload }), $"{(CommandCode)frame.Command} payload {payload.Length} bytes");
            case 3:
                var garbage = new byte[random.Next(1, 300)];
                random.NextBytes(garbage);
                return ([(byte)'<', .. garbage], $"'<' and {garbage.Length} random bytes");
            default:
                FrameCodec.TryDecode(valid, out var good, out _);
                var command = (byte)random.Next(0x09, 0x80);
                return (FrameCodec.Encode(good with { Command = command, Payload = ImmutableArray<byte>.Empty }), $"command {command:X2}");
        }
    }
}
