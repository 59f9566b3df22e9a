using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// Seeded random requests against the generated handler in the STL interpreter and the reference model side by side:
/// every command and unknown ones, payloads of the right and wrong length, items at and past the end of every area
/// (the handler's V bytes moved down so V's last bytes are the user's), lists of every size with memory changing
/// between READ LISTs, writes, and frames that must get no reply (bad check, another station, LEN not the count,
/// longer than the buffer). Every answer must be the reference's, byte for byte, and the station must answer the next
/// request: no request leaves it silent (issue 23; v2's handler once went silent on the last bytes of an area).
/// </summary>
public sealed class V3FuzzTests
{
    /// <summary>SM bytes the CPU or the handler itself change while it works (scan times, SM0/SM1, the receive status), which the reference model does not; the fuzz reads them nowhere.</summary>
    private static bool Volatile(ProtocolArea area, int offset, int length) =>
        area == ProtocolArea.SM && (offset < 30 || Overlaps(offset, length, 86, 9) || Overlaps(offset, length, 186, 9));

    private static bool Overlaps(int offset, int length, int first, int count) => offset < first + count && first < offset + length;

    [Theory]
    [InlineData(CpuModel.Cpu224, false, 4000, 51)]
    [InlineData(CpuModel.Cpu226, false, 6000, 52)]
    [InlineData(CpuModel.Cpu221, true, 1000, 53)]
    [InlineData(CpuModel.Cpu222, true, 1200, 54)]
    public void RandomRequests_AnswerLikeTheReferenceAndNeverSilenceTheStation(CpuModel cpu, bool compact, int vFirst, int seed)
    {
        var random = new Random(seed);
        var station = new V3Station(new HandlerOptions { Cpu = CpuProfiles.For(cpu), Station = 7, Compact = compact, BufferStart = vFirst }, new Random(seed + 100));
        var fuzz = new Fuzz(station, random);
        var answered = 0;
        for (var i = 0; i < (compact ? 150 : 300); i++)
        {
            fuzz.PokeSomething();
            var (frame, how) = fuzz.Next();
            var (stl, reference) = station.Exchange(frame);
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(reference), $"#{i} {how}: {Convert.ToHexString(frame)}");
            answered += stl.Length > 0 ? 1 : 0;
            if (i % 10 == 9)
            {
                var (identify, _) = station.Exchange(Codec.Encode(Request.Identify(station.Station, fuzz.Sequence())));
                identify.Should().NotBeEmpty($"the station answers IDENTIFY after request #{i}");
            }
        }

        answered.Should().BeGreaterThan(compact ? 90 : 180, "most fuzz frames are well-formed requests, answered or refused");
        station.Plc.Fault.Should().BeNull();
    }

    /// <summary>The request generator; its frames avoid reading what the reference cannot know (the handler's own V bytes, volatile SM).</summary>
    private sealed class Fuzz(V3Station station, Random random)
    {
        private readonly Func<ProtocolArea, int> _size = ListPlan.AreaBytesOf(station.Options.Cpu);
        private readonly int _vFirst = station.Generated.Stats!.FirstVByte;
        private readonly int _vLast = station.Generated.Stats!.LastVByte;
        private byte _sequence;
        private List<ReadItem> _listed = [];

        public byte Sequence() => _sequence = (byte)((_sequence + 1) % Limits.SequenceCount);

        /// <summary>Now and then a byte of I, Q, M or V changes, as the machine's program would change it.</summary>
        public void PokeSomething()
        {
            if (random.Next(2) != 0)
            {
                return;
            }

            // Mostly a byte of the list's windows (so READ LIST finds CHANGES), else anywhere.
            var listed = _listed.Where(r => r.Area != ProtocolArea.SM).ToList();
            var (area, offset) = listed.Count > 0 && random.Next(3) != 0 && listed[random.Next(listed.Count)] is var item
                ? (item.Area, item.Offset + random.Next(4))
                : (new[] { ProtocolArea.I, ProtocolArea.Q, ProtocolArea.M, ProtocolArea.V }[random.Next(4)], -1);
            offset = offset < 0 ? Offset(area) : offset;
            if (offset < _size(area) && !Own(area, offset, 1))
            {
                station.Poke(area, offset, (byte)random.Next(256));
            }
        }

        public (byte[] Frame, string How) Next()
        {
            var roll = random.Next(100);
            if (roll < 6)
            {
                return Broken();
            }

            var (request, how) = roll switch
            {
                < 28 => (Request.Read(station.Station, Sequence(), ReadableItem()), "READ"),
                < 40 => Write(),
                < 48 => (Request.WriteBits(station.Station, Sequence(), Area(), Offset(Area()), (byte)random.Next(256), (byte)random.Next(256)), "WRITE BITS"),
                < 54 => DefineList(),
                < 81 => (Request.ReadList(station.Station, Sequence()), "READ LIST"),
                < 87 => (Request.ReadListFull(station.Station, Sequence()), "READ LIST FULL"),
                < 91 => (Request.Identify(station.Station, Sequence()), "IDENTIFY"),
                _ => (new Request(station.Station, Sequence(), (Command)random.Next(16), [.. Bytes(random.Next(0, 9))]), "any command, any payload"),
            };
            var frame = Codec.Encode(request);
            return frame.Length > station.Reference.Setup.Shape.RequestBytes ? Next() : (frame, how);
        }

        private (Request, string) Write()
        {
            var area = Area();
            var length = random.Next(4) == 0 ? random.Next(0, 18) : random.Next(1, 5);
            var offset = random.Next(4) == 0 ? _vFirst - random.Next(0, 6) : Offset(area);
            var request = Request.Write(station.Station, Sequence(), random.Next(4) == 0 ? ProtocolArea.V : area, offset, Bytes(length));
            return random.Next(8) == 0
                ? (request with { Payload = [.. request.Payload, .. Bytes(1)] }, "WRITE, P not 4 + LENGTH")
                : (request, "WRITE");
        }

        /// <summary>Frames no station may answer: a flipped bit, another station, LEN not the count, too long for the buffer.</summary>
        private (byte[], string) Broken()
        {
            var frame = Codec.Encode(Request.Read(station.Station, Sequence(), ReadableItem()));
            switch (random.Next(4))
            {
                case 0:
                    frame[random.Next(1, frame.Length)] ^= (byte)(1 << random.Next(8));
                    return (frame, "a bit flipped");
                case 1:
                    return (Codec.Encode(Request.Identify(new Core.Addressing.Station((station.Options.Station % 126) + 1), Sequence())), "another station");
                case 2:
                    return ([.. frame, (byte)random.Next(256)], "one byte more than LEN");
                default:
                    var items = Enumerable.Range(0, (station.Reference.Setup.Shape.RequestBytes / 4) + 1).Select(_ => new ReadItem(ProtocolArea.M, 0, 1));
                    return (Codec.Encode(Request.DefineList(station.Station, Sequence(), items)), "longer than the buffer");
            }
        }

        private int ListLength() => random.Next(5) switch
        {
            0 => random.Next(0, 34),
            1 => 8,
            2 => 16,
            3 => 24,
            _ => 32,
        };

        /// <summary>Mostly a list the handler takes (every item and its window inside its area), sometimes one with anything in it.</summary>
        private (Request, string) DefineList()
        {
            var good = random.Next(10) < 8;
            var items = Enumerable.Range(0, good ? 8 * random.Next(1, 5) : ListLength()).Select(_ => ListItem(good)).ToList();
            _listed = items;
            return (Request.DefineList(station.Station, Sequence(), items), good ? "DEFINE LIST, every item valid" : "DEFINE LIST, anything");
        }

        /// <summary>An item for a list: its 4-byte window (from its first byte) must avoid what the reference cannot know.</summary>
        private ReadItem ListItem(bool good)
        {
            while (true)
            {
                var area = Area();
                var item = good
                    ? new ReadItem(area, Math.Max(0, Offset(area) - 4), random.Next(1, 5))
                    : new ReadItem(area, Offset(area), random.Next(6) == 0 ? random.Next(0, 6) : random.Next(1, 5));
                if (good && item.Offset + 4 > _size(area))
                {
                    continue;
                }

                if (!Own(item.Area, item.Offset, 4) && !Volatile(item.Area, item.Offset, 4))
                {
                    return item;
                }
            }
        }

        private ReadItem ReadableItem()
        {
            while (true)
            {
                var area = random.Next(12) == 0 ? (ProtocolArea)random.Next(7) : Area();
                var length = random.Next(5) == 0 ? random.Next(0, 18) : random.Next(1, 17);
                var item = new ReadItem(area, Offset(area), length);
                if (!Own(item.Area, item.Offset, Math.Max(1, item.Length)) && !Volatile(item.Area, item.Offset, Math.Max(1, item.Length)))
                {
                    return item;
                }
            }
        }

        private ProtocolArea Area() => (ProtocolArea)random.Next(1, 6);

        /// <summary>The area's first or last bytes, just past its end, far past it, or anywhere in it.</summary>
        private int Offset(ProtocolArea area)
        {
            var size = area is >= ProtocolArea.I and <= ProtocolArea.SM ? _size(area) : 100;
            return random.Next(8) switch
            {
                0 => random.Next(0, 4),
                1 or 2 => Math.Max(0, size - random.Next(1, 6)),
                3 => size + random.Next(0, 3),
                4 => new[] { 0x27FF, 0x2800, 0xFFFF }[random.Next(3)],
                _ => random.Next(0, size),
            };
        }

        private bool Own(ProtocolArea area, int offset, int length) => area == ProtocolArea.V && Overlaps(offset, length, _vFirst, _vLast - _vFirst + 1);

        private byte[] Bytes(int count)
        {
            var bytes = new byte[count];
            random.NextBytes(bytes);
            return bytes;
        }
    }
}
