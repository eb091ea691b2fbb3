#include "voidFractionModel.H"

Foam::autoPtr<Foam::voidFractionModel> Foam::voidFractionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("voidFractionModel"));

    Info<< "Selecting voidFractionModel " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "voidFractionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<voidFractionModel>(cstrIter()(modelType, dict, mesh));
}
