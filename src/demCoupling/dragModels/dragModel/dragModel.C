#include "dragModel.H"

namespace Foam
{
    defineTypeNameAndDebug(dragModel, 0);
    defineRunTimeSelectionTable(dragModel, dictionary);
}


Foam::autoPtr<Foam::dragModel> Foam::dragModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("dragModel"));

    Info<< "Selecting dragModel " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "dragModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<dragModel>(cstrIter()(dict));
}
