using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>Valid requests and matching replies drawn from a seeded <see cref="Random"/>: every command, every area, lengths up to the limits.</summary>
internal static class RandomMessages
{
    private static readonly ProtocolArea[] Areas = Enum.GetValues<ProtocolArea>();

    public static PlcRequest Request(Random rng)
    {
        var station = new Station(rng.Next(Station.Min, Station.Max + 1));
        var sequence = (byte)rng.Next(256);
        return rng.Next(9) switch
        {
            8 => new ReadChangesOfListsRequest(station, sequence, (byte)rng.Next(1, ProtocolLimits.ListMaskBits + 1)),
            6 => new StopRequest(station, sequence),
            7 => new ReadChangesRequest(station, sequence, rng.Next(1, ProtocolLimits.MaxLists + 1), rng.Next(2) == 1),
            4 => new DefineListRequest(station, sequence, rng.Next(1, ProtocolLimits.MaxLists + 1), Items(rng)),
            5 => new ReadListRequest(station, sequence, rng.Next(1, ProtocolLimits.MaxLists + 1)),
            0 => new IdentifyRequest(station, sequence),
            1 => new ReadRequest(station, sequence, Items(rng)),
            2 => new WriteBlockRequest(station, sequence, Area(rng), rng.Next(65536), Bytes(rng, rng.Next(1, ProtocolLimits.MaxWriteData + 1))),
            _ => new WriteBitRequest(station, sequence, Area(rng), rng.Next(65536), rng.Next(8), rng.Next(2) == 1),
        };
    }

    /// <summary>
    /// A reply to <paramref name="request"/> carrying its REQCHECK: mostly OK with random data, sometimes an error code 02-07.
    /// </summary>
    public static PlcResponse ResponseTo(Random rng, PlcRequest request) => Reply(rng, request) with { RequestCheck = RequestCodec.Check(request) };

    private static PlcResponse Reply(Random rng, PlcRequest request)
    {
        var (station, sequence) = (request.Station, request.Sequence);
        if (rng.Next(5) == 0)
        {
            return new ErrorResponse(station, sequence, request.Command, (ProtocolError)rng.Next(2, 8));
        }

        return request switch
        {
            IdentifyRequest => new IdentifyResponse(
                station, sequence, HandlerIdentity.ProtocolVersion, 1, (byte)rng.Next(1, 6), (byte)rng.Next(2), (byte)rng.Next(256), HandlerIdentity.MaxReadData, (byte)rng.Next(1, 256),
                (byte)rng.Next(256), (byte)rng.Next(2), (ushort)rng.Next(65536), (ushort)rng.Next(65536), (ushort)rng.Next(65536),
                (byte)rng.Next(2), (ushort)rng.Next(65536), (ushort)rng.Next(65536), (byte)rng.Next(4), (byte)rng.Next(256)),
            ReadRequest read => new ReadResponse(station, sequence, Bytes(rng, read.TotalLength)),
            WriteBlockRequest write => new WriteBlockResponse(station, sequence, Bytes(rng, write.Data.Length)),
            DefineListRequest => new DefineListResponse(station, sequence),
            ReadListRequest => new ReadListResponse(station, sequence, Bytes(rng, rng.Next(1, ProtocolLimits.MaxReadData + 1))),
            StopRequest => new StopResponse(station, sequence),
            ReadChangesRequest when rng.Next(2) == 0 => ReadChangesResponse.Whole(station, sequence, Bytes(rng, rng.Next(1, ProtocolLimits.MaxReadData + 1))),
            ReadChangesRequest => ReadChangesResponse.Pairs(station, sequence, Changes(rng)),
            ReadChangesOfListsRequest lists => new ReadChangesOfListsResponse(station, sequence, [.. lists.Lists.Select(list => Entry(rng, list))]),
            _ => new WriteBitResponse(station, sequence, (byte)rng.Next(256)),
        };
    }

    public static ImmutableArray<byte> Bytes(Random rng, int count)
    {
        var bytes = new byte[count];
        rng.NextBytes(bytes);
        return [.. bytes];
    }

    /// <summary>A REREAD entry one time in three, else 0-10 ascending pairs: four entries stay within one reply.</summary>
    private static ListChanges Entry(Random rng, int list) => rng.Next(3) == 0
        ? ListChanges.RereadList(list)
        : ListChanges.Pairs(list, [.. Enumerable.Range(0, 40).Where(_ => rng.Next(4) == 0).Take(10).Select(i => new ChangedByte((byte)i, (byte)rng.Next(256)))]);

    /// <summary>0-57 pairs (fewer than half of the largest list's 116 bytes), ascending distinct indexes.</summary>
    private static ImmutableArray<ChangedByte> Changes(Random rng) =>
        [.. Enumerable.Range(0, ProtocolLimits.MaxReadData).Where(_ => rng.Next(4) == 0).Take(57).Select(i => new ChangedByte((byte)i, (byte)rng.Next(256)))];

    private static ProtocolArea Area(Random rng) => Areas[rng.Next(Areas.Length)];

    private static ImmutableArray<ReadItem> Items(Random rng)
    {
        var count = rng.Next(1, ProtocolLimits.MaxReadItems + 1);
        var budget = ProtocolLimits.MaxReadDataFor(count) - count;
        var items = ImmutableArray.CreateBuilder<ReadItem>(count);
        for (var i = 0; i < count; i++)
        {
            var extra = rng.Next(budget + 1);
            budget -= extra;
            items.Add(new ReadItem(Area(rng), rng.Next(65536), 1 + extra));
        }

        return items.MoveToImmutable();
    }
}
